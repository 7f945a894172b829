"""The function a probe calls and the program that calls it (probes.py's module doc: "The
function" and "The probe program"), read from an answer's syntax tree."""
from __future__ import annotations

import ast
import functools

from sartco.syntax import parse


def _top_defs(tree: ast.Module) -> set[str]:
    return {s.name for s in tree.body if isinstance(s, (ast.FunctionDef, ast.AsyncFunctionDef))}


def _calls(node: ast.AST):
    """Calls in source order, not descending into def, lambda or class bodies."""
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
        return
    if isinstance(node, ast.Call):
        yield node
    for child in ast.iter_child_nodes(node):
        yield from _calls(child)


def _passes_board(call: ast.Call) -> bool:
    first = call.args[0] if call.args else next((k.value for k in call.keywords if k.arg == "board"), None)
    return isinstance(first, ast.Name) and first.id == "board"


# an answer's probe programs read its tree twice in a row (probed_call, then without_usage), and
# nothing here changes a tree: the last few are kept
@functools.lru_cache(maxsize=8)
def _parse(code: str) -> ast.Module | None:
    try:
        return parse(code)
    except (SyntaxError, ValueError):
        return None


def probed_function(code: str, given_code: str = "") -> str | None:
    """The name of the function `code`'s usage calls (module doc), None when it calls none."""
    found = probed_call(code, given_code)
    return None if found is None else found[0]


@functools.lru_cache(maxsize=4096)  # each step asks it of the episode's gold and of the answer
def probed_call(code: str, given_code: str = "") -> tuple[str, str] | None:
    """The function `code`'s usage calls (module doc) and whose def it is: (name, "model") when a
    top-level def of `code` defines it, (name, "given") when only the given code does; None when
    it calls none. One parse of each text for both."""
    tree, given = _parse(code), _parse(given_code) or ast.Module(body=[], type_ignores=[])
    if tree is None:
        return None
    own = _top_defs(tree)
    defined = own | _top_defs(given)
    for statement in tree.body:
        for call in _calls(statement):
            if isinstance(call.func, ast.Name) and call.func.id in defined and _passes_board(call):
                return call.func.id, "model" if call.func.id in own else "given"
    return None


@functools.lru_cache(maxsize=1024)  # a draw's candidates and an answer's probes share it
def without_usage(code: str, name: str) -> str:
    """`code` without its top-level statements that call `name` (the usage line or loop)."""
    tree = _parse(code)
    lines = code.splitlines()
    drop: set[int] = set()
    for s in tree.body if tree else []:
        if any(isinstance(c.func, ast.Name) and c.func.id == name for c in _calls(s)):
            drop.update(range(s.lineno - 1, s.end_lineno or s.lineno))
    return "\n".join(line for i, line in enumerate(lines) if i not in drop)


def probe_head(code: str, name: str, *, given_code: str, rows: int, cols: int) -> str:
    """A probe program but its last line (the same for each of an answer's probes): the given code,
    the answer without its usage, a fresh board."""
    parts = [given_code.strip(), without_usage(code, name).strip(), f"board = init_board({rows}, {cols})"]
    return "\n".join(p for p in parts if p) + "\n"


def probe_call(name: str, args: dict) -> str:
    """A probe program's last line: the function at the probe's arguments."""
    return f"{name}(board, {list(args['colors'])!r}, {args['x']}, {args['y']})\n"
