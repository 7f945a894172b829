"""`match` statements: what their value and class patterns read goes through the attribute rule.

Python reads names and attributes inside a pattern itself (`case Color.RED:`, `case
shapes.Point(x=0):`), and a class pattern reads the subject's attributes with the interpreter's
own getattr. So nodes.py rewrites the name of every value pattern and class pattern to an
attribute of PATTERNS (the builtin `$pattern`, which no source can spell) that holds its text:
`case Color.RED:` becomes `case $pattern.v:Color.RED:` and `case Point(1, y=2):` becomes
`case $pattern.c1:Point:y(...)` (c, the number of positional sub-patterns, the dotted name, the
keyword names). When Python tries that case (not before: as lazily as Python), `PATTERNS`
resolves the dotted name in the program's frame as Python would (locals, globals, builtins; every
attribute by attributes.read) and, for a class, hands Python a stand-in class (Pattern) that
- matches what the class matches (`isinstance`), Python's `int`/`str` for the program's own;
- before Python reads an attribute of the subject (the keyword names, and `__match_args__`'s
  names for the positional sub-patterns), asks the rule whether the program may read that name
  on that object (attributes.read without reading it): a refused name is `forbidden`, a name the
  rule hides makes the pattern fail, as an attribute the object does not have; a name the
  budgets must see (str's `ljust`, ...) is refused, never read unchecked;
- matches the subject itself for one positional sub-pattern where Python does (`case int(n):`,
  bool, float, str, bytes, list, tuple, dict, set, frozenset and their subclasses, without
  `__match_args__`).
Sequence and mapping patterns index the subject and call a mapping's `get`, which the program
may do anyway; captures, `_`, `|`, `as` and guards are Python's own.
"""
from __future__ import annotations

import sys
from typing import Any

from .attributes import read
from .budget import Forbidden
from .classes import READABLE
from .conversions import INT, STR
from .methods import CHECKED_METHODS

_SELF_MATCHING = (bool, bytearray, bytes, dict, float, frozenset, int, list, set, str, tuple)
_REAL = {INT: int, STR: str}


def _nothing(obj: Any, name: str) -> None:
    """The rule's fetch for a pattern: Python reads the attribute itself, once."""
    return None


class _PatternType(type):
    """The type of a class pattern's stand-in class: an isinstance that also checks the rule."""

    _real: type  # the class the pattern names
    _reads: tuple[Any, ...]  # the names Python will read of a subject that is one

    def __instancecheck__(cls, subject: Any) -> bool:
        if not isinstance(subject, cls._real):
            return False
        for name in cls._reads:
            if type(name) is not str:  # Python says it again: "__match_args__ elements must be strings"
                return True
            if name[:2] == "__" and name not in READABLE:  # (a program's __match_args__ may name one)
                raise Forbidden(f"attributes starting with two underscores reach the interpreter: .{name}")
            if name in CHECKED_METHODS:
                raise Forbidden(f"a class pattern cannot read .{name}: the budgets check it only when called")
            try:
                read(subject, name, _nothing)
            except AttributeError:
                return False  # the rule hides it: the pattern does not match, as for a missing attribute
        return True


_CACHE: dict[tuple[Any, ...], type] = {}  # (class, positional sub-patterns, keyword names) -> its stand-in


def _class_pattern(real: Any, positional: int, keywords: tuple[str, ...]) -> Any:
    real = _REAL.get(real, real)
    if not isinstance(real, type):
        return real  # Python raises: "called match pattern must be a class"
    key = (real, positional, keywords)
    made = _CACHE.get(key)
    if made is None:
        # the class's own or inherited __match_args__, as Python looks it up (never the metaclass's)
        match_args = next((k.__dict__["__match_args__"] for k in real.__mro__ if "__match_args__" in k.__dict__), None)
        namespace: dict[str, Any] = {"__slots__": (), "_real": real}
        if match_args is not None:
            namespace["__match_args__"] = match_args
            names = tuple(match_args[:positional]) if type(match_args) is tuple else ()
        else:  # Python binds the subject itself where the class is one of _SELF_MATCHING's
            names = ()
        namespace["_reads"] = names + keywords
        bases = (int,) if match_args is None and issubclass(real, _SELF_MATCHING) else ()
        made = _CACHE[key] = _PatternType(real.__name__, bases, namespace)
    return made


def _resolve(dotted: str, frame: Any) -> Any:
    """A dotted name as Python reads it in `frame` (locals, globals, builtins), each attribute by
    the attribute rule."""
    first, *rest = dotted.split(".")
    for space in (frame.f_locals, frame.f_globals, frame.f_globals["__builtins__"]):
        if first in space:
            value = space[first]
            break
    else:
        raise NameError(f"name {first!r} is not defined")
    for name in rest:
        value = read(value, name)
    return value


class Patterns:
    """`$pattern`: its attribute `v:<dotted>` is a value pattern's value, `c<n>:<dotted>:<k,...>` a
    class pattern's class (see the module's docstring)."""

    __slots__ = ()

    def __getattr__(self, key: str) -> Any:
        kind, dotted, keywords = (key.split(":") + [""])[:3]
        value = _resolve(dotted, sys._getframe(1))  # the frame of the program's match statement
        if kind == "v":
            return value
        return _class_pattern(value, int(kind[1:]), tuple(filter(None, keywords.split(","))))


PATTERNS = Patterns()
