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

from sartco.syntax import parse

from .allowed import ALLOWED_BUILTINS, EXCEPTIONS, WHAT
from ..standins.budget import Forbidden
from ..standins.classes import FILENAME
from ..standins.modules import MEMBERS
from .nodes import PLAN, WRAPS
from .walk import Walk, check_name, fail

__all__ = ["instrument", "prepare"]


def instrument(tree: ast.Module) -> ast.Module:
    """Check every node and instrument in place; raise the Forbidden that comes first in the text.

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
    return tree


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


def prepare(source: str):
    """Parse, check and instrument; return a code object. Raises SyntaxError or Forbidden."""
    tree = parse(source, FILENAME)
    return compile(instrument(tree), FILENAME, "exec", dont_inherit=True, optimize=0)  # asserts run, whatever -O
