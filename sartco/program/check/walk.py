"""What one walk of a program's tree has seen (Walk), and the checks of names that every rule uses:
`fail` (a refusal at a node), `check_name` (a name bound or read), `check_attribute_name` (a
name read or written as `x.name`); `located` puts a new node at an old one's place."""
from __future__ import annotations

import ast
from typing import Any, NoReturn

from .allowed import ATTRIBUTES, DENIED, PROVIDED
from ..standins.budget import Forbidden
from ..standins.classes import DEFINABLE, READABLE


def fail(node: Any, text: str) -> NoReturn:
    line = getattr(node, "lineno", None)
    exc = Forbidden(f"line {line}: {text}" if line else text)
    exc.position = (line or 0, getattr(node, "col_offset", 0))
    raise exc


class Walk:
    """What one walk has seen: names the program binds, builtins it reads that are not there."""

    __slots__ = ("stored", "denied", "methods", "reads", "strings", "modules")

    def __init__(self) -> None:
        self.stored: set[str] = set()  # names bound, attributes stored
        self.denied: dict[str, ast.AST] = {}
        self.methods: set[int] = set()  # the defs and names of a class body that bind DEFINABLE dunders
        self.reads: dict[str, ast.AST] = {}  # attributes read that the sandbox does not offer
        self.strings: list[str] = []  # the string constants (their words may name namedtuple fields)
        self.modules: dict[str, str] = {}  # name bound by an import -> module


def check_name(node: Any, name: str, store: bool, walk: Walk) -> None:
    if name[0] == "$":  # ours: no Python source can spell it
        return
    if name[0] == "_" and name[:2] == "__" and (id(node) not in walk.methods if store else name not in DEFINABLE and name != "__name__"):
        fail(node, f"names starting with two underscores reach the interpreter: {name}")
    if store:
        if name in PROVIDED:
            fail(node, f"{name} is the task's world and cannot be redefined")
        walk.stored.add(name)
    elif name in DENIED and name not in walk.denied:
        walk.denied[name] = node  # refused at the end unless the program binds the name itself


def located(new: Any, old: Any) -> Any:
    """`new` at `old`'s place in the source (for messages and the compiler)."""
    new.lineno = old.lineno
    new.col_offset = old.col_offset
    new.end_lineno = old.end_lineno
    new.end_col_offset = old.end_col_offset
    return new


def check_attribute_name(n: ast.Attribute, walk: Walk) -> None:
    """A name read or written as `x.name`: no dunder but those a program may read; a name the
    sandbox does not offer must be one the program defines (checked at the end of the walk)."""
    name = n.attr
    if name[:2] == "__" and ((name not in DEFINABLE and name not in READABLE) or type(n.ctx) is not ast.Load):
        fail(n, f"attributes starting with two underscores reach the interpreter: .{name}")
    if type(n.ctx) is not ast.Load:
        walk.stored.add(name)
    elif name not in ATTRIBUTES and name[:2] != "__" and (name not in walk.reads or type(n.value) is ast.Name):
        walk.reads[name] = n  # (a module's name as the owner makes the clearer message)
