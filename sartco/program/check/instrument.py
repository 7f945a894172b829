"""Validate a program's syntax tree and instrument it for the budgets, in one pass.

Pure: nothing here runs model code. `prepare(source)` returns a code object or raises
`Forbidden` (a construct outside the allowed subset, allowed.py) / SyntaxError.

The check looks at the parsed tree, never at the text: the parser normalises full-width Unicode
identifiers (NFKC), so `ｅｖａｌ` arrives here as `eval`. What each node type may be and how it
is instrumented is in nodes.py. The walk is one linear pass over the tree (no search inside
lists: a 100 KB display checks in about the time compile() takes).
"""
from __future__ import annotations

import ast
import re
from types import CodeType

from sartco.syntax import parse

from .allowed import ALLOWED_BUILTINS, EXCEPTIONS, WHAT
from ..standins.budget import Forbidden
from ..standins.classes import FILENAME
from ..standins.modules import MEMBERS
from .nodes import PLAN, WRAPS
from .walk import Walk, check_name, fail

__all__ = ["Head", "instrument", "judge", "prepare", "split", "walked"]


def instrument(tree: ast.Module) -> ast.Module:
    """Check every node and instrument in place; raise the Forbidden that comes first in the text."""
    judge(*walked(tree))
    return tree


def walked(tree: ast.Module) -> tuple[Walk, list[Forbidden]]:
    """Check every node and instrument in place: what the walk saw, and the offences of single
    nodes (judge adds those of the whole program and raises the first).

    One iterative pass (no recursion limit to hit); leaves (names, constants) are handled
    where they are met, because they make up two thirds of a typical tree. After an offence the
    walk goes on (without the offending node's remaining children), so that the offence
    reported is the first one in the source, not the first one visited."""
    todo = [tree]
    pop, push = todo.pop, todo.append
    wrapped: set[int] = set()
    seen_loads: set[str] = set()  # names already checked in a load context
    offences: list[Forbidden] = []
    walk = Walk()
    plan_of, wrap_of, name_type, const_type, load_type = PLAN.get, WRAPS.get, ast.Name, ast.Constant, ast.Load

    while todo:
        node = pop()
        try:
            t = type(node)
            plan = plan_of(t)
            if plan is None:
                fail(node, f"{WHAT.get(t) or t.__name__} is not allowed")
            rule, fields = plan
            if rule is not None:
                rule(node, walk)
            for field, many in fields:
                value = getattr(node, field)
                k = 0  # where the last replaced child was: each list is searched once, in order
                for child in value if many else (value,):
                    ct = type(child)
                    if ct is const_type or child is None:
                        if ct is const_type and type(child.value) is str and id(child) not in wrapped:
                            walk.strings.append(child.value)
                        continue
                    if ct is name_type:
                        if type(child.ctx) is not load_type:
                            check_name(child, child.id, True, walk)
                        elif child.id not in seen_loads:
                            check_name(child, child.id, False, walk)
                            seen_loads.add(child.id)
                        continue
                    wrap = wrap_of(ct)
                    if wrap is not None:
                        new = wrap(child, wrapped, walk)
                        if new is not child:
                            if many:
                                k = value.index(child, k)  # nodes compare by identity
                                value[k] = new
                            else:
                                setattr(node, field, new)
                            child = new
                    push(child)
        except Forbidden as exc:
            offences.append(exc)
    return walk, offences


def judge(walk: Walk, offences: list[Forbidden]) -> None:
    """Raise the first in the text of `offences` and of the whole program's (a builtin it reads
    but the sandbox refuses and it never binds; an attribute it reads that nothing offers)."""
    offences = list(offences)
    for name, node in walk.denied.items():
        if name not in walk.stored:
            try:
                fail(node, f"{name} is not available in the sandbox: it reaches the interpreter, files or the "
                           f"terminal (builtins here: {', '.join(sorted(ALLOWED_BUILTINS - EXCEPTIONS))})")
            except Forbidden as exc:
                offences.append(exc)
    _undefined_attributes(walk, offences)
    if offences:
        raise min(offences, key=lambda exc: exc.position)


def _undefined_attributes(walk: Walk, offences: list):
    """An attribute read that the sandbox does not offer must be a name the program defines."""
    if not walk.reads:
        return
    defined = walk.stored.union(*(re.findall(r"[A-Za-z_]\w*", s) for s in walk.strings))
    for name, node in walk.reads.items():
        if name in defined:
            continue
        owner = node.value.id if type(node.value) is ast.Name else None
        module = walk.modules.get(owner)
        if module:
            text = f"{module}'s {name} is not available in the sandbox (available: {', '.join(sorted(MEMBERS[module]))})"
        else:
            text = (f"attribute .{name} is not available in the sandbox (only the common methods of str, list, "
                    f"dict, set and tuple, the members of the allowed modules and what the program defines)")
        try:
            fail(node, text)
        except Forbidden as exc:
            offences.append(exc)


def prepare(source: str, heads: dict[str, Head | None] | None = None) -> CodeType | tuple[CodeType, CodeType]:
    """Parse, check and instrument; return a code object. Raises SyntaxError or Forbidden.

    `heads`: the heads (Head) made so far for a batch of programs that may share theirs; a
    program's code is then (its head's code, its last line's code) where `_inert` allows, and its
    head is made once. Every parse and compile here is at the depth of a whole program's (the
    same nesting limit)."""
    if heads is not None and (parts := split(source)) is not None:
        text, last = parts
        if text not in heads:  # a head that does not compile alone or is refused: its programs are prepared whole
            try:
                walk, offences = walked(tree := parse(text, FILENAME))
                heads[text] = None if offences else Head(text.count("\n") + 1, walk, _compiled(tree))
            except (SyntaxError, ValueError):
                heads[text] = None
        head = heads[text]
        if head is not None:
            try:
                line = parse("\n" * head.lines + last, FILENAME)  # at its own line numbers
                if _inert(head, line):
                    return head.code, _compiled(line)
            except (SyntaxError, ValueError):  # (then the whole program says why)
                pass
    return _compiled(instrument(parse(source, FILENAME)))


def _compiled(tree: ast.Module) -> CodeType:
    return compile(tree, FILENAME, "exec", dont_inherit=True, optimize=0)  # asserts run, whatever -O


class Head:
    """A program's text but its last line, checked and compiled once for the programs of a batch
    that differ from each other only in that line (an answer's probes, a gold draw's candidates):
    its lines, what its walk saw and its code."""

    __slots__ = ("lines", "walk", "code")

    def __init__(self, lines: int, walk: Walk, code: CodeType) -> None:
        self.lines, self.walk, self.code = lines, walk, code


def split(source: str) -> tuple[str, str] | None:
    """(head, last line) of a program that may share its head, else None: one line only, a
    __future__ import (it would change how its last line compiles), or a carriage return (a
    line break that the count of lines would miss)."""
    cut = source.rfind("\n", 0, len(source) - 1)
    return None if cut < 0 or "__future__" in source or "\r" in source else (source[:cut], source[cut + 1:])


def _inert(head: Head, tree: ast.Module) -> bool:
    """Whether the head's code and the code of the last line `tree` do what the whole program's
    code does, and pass the check as it does (else Forbidden as prepare raises): they do when the
    last line holds only expressions that bind, read and refuse nothing.

    The same because: head and last line each parse alone and the last line starts a statement
    at column 0, so no statement continues across them; the walk's verdict on a node depends on
    the names the program binds and the words of its strings, to which such a last line adds only
    its strings; and two code objects run one after the other in one namespace (runtime._run) do
    what the module's one code does, unless the second starts with a string (its docstring: it
    would bind __doc__)."""
    walk, offences = walked(tree)
    if (offences or walk.stored or walk.denied or walk.reads or walk.modules or walk.methods
            or any(type(statement) is not ast.Expr for statement in tree.body)
            or ast.get_docstring(tree) is not None):
        return False
    whole = Walk()
    whole.stored, whole.denied, whole.reads, whole.modules = head.walk.stored, head.walk.denied, head.walk.reads, head.walk.modules
    whole.strings = head.walk.strings + walk.strings
    judge(whole, [])
    return True
