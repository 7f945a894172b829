"""The rules of `match` statements' patterns (nodes.py's RULES): a value pattern's dotted name and
a class pattern's class become attributes of `$pattern` that name them (`$pattern.v:Color.RED`,
`$pattern.c1:Point:y`), resolved when the case is tried and read through the attribute rule
(standins/patterns.py); names a pattern binds are checked as any name bound."""
from __future__ import annotations

import ast
from typing import Any

from ..standins.classes import READABLE
from .walk import Walk, check_attribute_name, check_name, fail, located

_LOAD = ast.Load()


def _dotted(node: Any, walk: Walk) -> str:
    """The text of a pattern's dotted name (`Color.RED`), each part checked as a name or attribute is."""
    parts = []
    while type(node) is ast.Attribute:
        check_attribute_name(node, walk)
        parts.append(node.attr)
        node = node.value
    check_name(node, node.id, False, walk)
    return ".".join([node.id, *reversed(parts)])


def _pattern(key: str, old: Any) -> ast.Attribute:
    pattern: ast.Attribute = located(ast.Attribute(located(ast.Name("$pattern", _LOAD), old), key, _LOAD), old)
    return pattern


def _r_match_value(n: ast.MatchValue, walk: Walk) -> None:
    if type(n.value) is ast.Attribute:
        n.value = _pattern("v:" + _dotted(n.value, walk), n.value)


def _r_match_class(n: ast.MatchClass, walk: Walk) -> None:
    for name in n.kwd_attrs:  # read by the rule when the case is tried: a name nothing has is no match
        if name[:2] == "__" and name not in READABLE:
            fail(n, f"attributes starting with two underscores reach the interpreter: .{name}")
    n.cls = _pattern(f"c{len(n.patterns)}:{_dotted(n.cls, walk)}:{','.join(n.kwd_attrs)}", n.cls)


def _r_match_mapping(n: ast.MatchMapping, walk: Walk) -> None:
    n.keys = [_pattern("v:" + _dotted(key, walk), key) if type(key) is ast.Attribute else key for key in n.keys]
    if n.rest is not None:
        check_name(n, n.rest, True, walk)


def _r_match_capture(n: Any, walk: Walk) -> None:  # `case x`, `case [*rest]`, `case ... as x`
    if n.name is not None:
        check_name(n, n.name, True, walk)


MATCH_RULES = {
    ast.MatchValue: _r_match_value, ast.MatchClass: _r_match_class, ast.MatchMapping: _r_match_mapping,
    ast.MatchAs: _r_match_capture, ast.MatchStar: _r_match_capture,
}
