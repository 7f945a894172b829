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
import sys
from types import BuiltinMethodType, MethodType
from typing import Any

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
    """The type of every class a program defines (records.build_class makes them); a class hashes
    by serial_hash (type's hash is its address)."""

    def __repr__(cls):
        return f"<class '__main__.{type.__getattribute__(cls, '__qualname__')}'>"

    def __hash__(cls) -> int:
        return serial_hash(cls)


def is_program_object(obj) -> bool:
    """An instance of a program's class, or such a class."""
    return type(type(obj)) is ProgramClass or type(obj) is ProgramClass


SERIALS: dict[int, tuple] = {}  # id(object) -> (its hash, the object): the current program's
WIDE = sys.hash_info.width == 64  # _tuple_hash is CPython's 64-bit one


def serial_hash(obj) -> int:
    """The default hash of a program's objects (and of the stand-ins' objects a program makes:
    modules, generators of random, attrgetters, ...): the order in which they were first hashed,
    not their address, so that sets and dicts of them iterate alike in every worker."""
    entry = SERIALS.get(id(obj))
    if entry is None:
        entry = SERIALS[id(obj)] = (len(SERIALS), obj)  # held: no other object takes its id
    return entry[0]


_P1, _P2, _P5, _MASK = 11400714785074694791, 14029467366897019727, 2870177450012600261, (1 << 64) - 1
_IDENTITY: Any = object.__hash__  # the hash of functions, classes, None (3.11), exceptions, generators, ...


_TUPLE: Any = tuple.__hash__


def _tuple_hash(items: tuple[Any, ...]) -> int:
    """CPython's hash of a tuple (xxHash lanes, 64-bit), over program_hash of its items."""
    acc = _P5
    for item in items:
        acc = (acc + (program_hash(item) & _MASK) * _P2) & _MASK
        acc = (((acc << 31) | (acc >> 33)) & _MASK) * _P1 & _MASK
    acc = (acc + (len(items) ^ (_P5 ^ 3527539))) & _MASK
    if acc == _MASK:
        return 1546275796
    return acc - (1 << 64) if acc >> 63 else acc


def program_hash(value: Any) -> int:
    """The builtin `hash` of a program: Python's, except that what Python hashes by address (a
    function, a class, None, NaN, an exception, a generator, a bound method, a type, and tuples
    holding them) hashes by serial_hash, so that no hash a program sees depends on where an
    object lies in memory."""
    t = type(value)
    if t.__hash__ is _IDENTITY:
        return serial_hash(value)
    if t is float and value != value:  # NaN: Python 3.10+ hashes each NaN by its address
        return serial_hash(value)
    if t is tuple or t.__hash__ is _TUPLE:  # namedtuples too
        return _tuple_hash(value) if WIDE else hash(value)
    if t is MethodType:  # Python: the address of __self__ ^ the hash of __func__
        return serial_hash(value.__self__) ^ program_hash(value.__func__)
    if t is BuiltinMethodType:  # Python: the address of __self__ ^ the address of the C function
        return serial_hash(value.__self__) ^ hash(value.__name__)
    return hash(value)


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
