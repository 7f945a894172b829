"""The program's own classes: `class` statements, built by BUILD_CLASS (the `__build_class__` of
the sandbox's builtins, which every class statement calls) as instances of ProgramClass.

A class body runs as plain Python runs it (its code is instrumented like any other: loops and
method bodies count steps). Then the namespace is checked and the class made:
- bases: the program's own classes, the allowed exception classes (`class Bad(ValueError)`) and
  typing.NamedTuple (records.py); `object` is dropped by the check (nodes.py); no keywords
  (`metaclass=...`), so no metaclass, `__init_subclass__`, `__prepare__` or `__mro_entries__`
  of anything but ours ever runs;
- names: the dunder methods a program may define are DEFINABLE (construction, representation,
  comparison, containers, iteration, arithmetic); nothing that changes how Python itself treats
  the object (`__getattribute__`, `__getattr__`, `__setattr__`, `__del__`, `__new__`,
  `__init_subclass__`, `__set_name__`, `__get__`/`__set__`, `__reduce__`, `__deepcopy__`,
  `__index__`, `__class_getitem__`, `__slots__`, ...). nodes.py refuses the others before running;
  this check says it again for what reaches a class some other way.
Private names in a class (`self.__x`, `def __helper`) are mangled to `_Class__x` before the
check, as CPython mangles them (mangle_private). What a program may read and write on these
objects is attributes.py's rule.
"""
from __future__ import annotations

import ast
import builtins

from .budget import Forbidden

DEFINABLE = frozenset("""
    __init__ __post_init__ __repr__ __str__ __eq__ __ne__ __lt__ __le__ __gt__ __ge__ __hash__
    __len__ __iter__ __next__ __contains__ __getitem__ __setitem__ __delitem__ __bool__ __call__
    __add__ __sub__ __mul__ __truediv__ __floordiv__ __mod__ __pow__ __neg__ __pos__ __abs__
    __radd__ __rsub__ __rmul__ __rtruediv__ __rfloordiv__ __iadd__ __isub__ __imul__
    """.split())
EXCEPTIONS = frozenset(
    "Exception BaseException ValueError TypeError KeyError IndexError ZeroDivisionError ArithmeticError "
    "LookupError AttributeError RuntimeError StopIteration AssertionError NotImplementedError OverflowError "
    "NameError UnboundLocalError".split()
)
EXCEPTION_TYPES = frozenset(getattr(builtins, name) for name in EXCEPTIONS)  # the bases a class may have
# dunder attributes a program may read on its own objects (attributes.py): an instance's class
# (never a class's class: the metaclass is never reachable) and a class's name
READABLE = frozenset({"__class__", "__name__", "__qualname__"})
FILENAME = "<program>"  # the file name a program's code is compiled under (instrument.prepare)
COMPILER_NAMES = frozenset({"__module__", "__qualname__", "__annotations__", "__classcell__", "__doc__"})


class ProgramClass(type):
    """The type of every class a program defines (records.build_class makes them)."""

    def __repr__(cls):
        return f"<class '__main__.{type.__getattribute__(cls, '__qualname__')}'>"


def is_program_object(obj) -> bool:
    """An instance of a program's class, or such a class."""
    return type(type(obj)) is ProgramClass or type(obj) is ProgramClass


SERIALS: dict[int, tuple] = {}  # id(object) -> (its hash, the object): the current program's


def serial_hash(obj) -> int:
    """The default hash of a program's objects: the order in which they were first hashed, not
    their address, so that sets and dicts of them iterate alike in every worker."""
    entry = SERIALS.get(id(obj))
    if entry is None:
        entry = SERIALS[id(obj)] = (len(SERIALS), obj)  # held: no other object takes its id
    return entry[0]


def make(name: str, bases: tuple, namespace: dict):
    """A program class from a namespace whose names were checked (or are ours)."""
    for key in namespace:
        if key[:2] == "__" and key not in DEFINABLE and key not in COMPILER_NAMES and key != "__slots__":
            raise Forbidden(f"class {name}: defining {key} is not allowed (it changes how Python treats the object)")
    if "__hash__" not in namespace and "__eq__" not in namespace and all(
            base.__hash__ is object.__hash__ or base.__hash__ is serial_hash for base in bases):
        namespace["__hash__"] = serial_hash
    return ProgramClass(name, bases, namespace)


_PRIVATE = {ast.Attribute: "attr", ast.FunctionDef: "name", ast.Name: "id"}  # the fields CPython mangles that we allow


def mangle_private(n: ast.ClassDef):
    """Private names (`self.__x`, `def __helper`) as CPython mangles them inside a class:
    `_Class__x`, a plain name (nested classes mangle their own)."""
    prefix = "_" + n.name.lstrip("_")
    todo = list(n.body)
    while todo:
        node = todo.pop()
        if type(node) is ast.ClassDef:
            todo.extend(node.decorator_list + node.bases)
            continue
        field = _PRIVATE.get(type(node))
        if field is not None:
            name = getattr(node, field)
            if name[:2] == "__" and name[-2:] != "__" and prefix != "_":
                setattr(node, field, prefix + name)
        todo.extend(ast.iter_child_nodes(node))
