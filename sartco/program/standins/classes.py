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
  `__index__`, `__class_getitem__`, ...). nodes.py refuses the others before running;
  this check says it again for what reaches a class some other way. A class body may also bind
  DATA: `__slots__` (names that are identifiers, never dunders: no `__dict__` slot) and
  `__match_args__` (what a class pattern of `match` reads, through the attribute rule: patterns.py);
- abstract methods (abc.py's ABC, `metaclass=ABCMeta`): a class with ABC among its bases gets
  `__abstractmethods__` as ABCMeta computes it (the names whose value has `__isabstractmethod__`,
  its own or inherited and not overridden), so that instantiating one raises Python's TypeError;
  no ABCMeta runs;
- enums: `class Color(Enum)` is made by ProgramEnumType, enum's own metaclass (EnumType) with the
  same check of the names (enums.py has the stand-in bases and what a program may read of them).
Private names in a class (`self.__x`, `def __helper`) are mangled to `_Class__x` before the
check, as CPython mangles them (mangle_private). What a program may read and write on these
objects is attributes.py's rule.
"""
from __future__ import annotations

import ast
import builtins
import collections
import enum
import sys
from types import BuiltinMethodType, MethodType
from typing import Any

from . import conversions
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
READABLE = frozenset({"__class__", "__name__", "__qualname__", "__members__"})  # (__members__: an enum's)
FILENAME = "<program>"  # the file name a program's code is compiled under (instrument.prepare)
# what the compiler puts in a class body's namespace (3.13 adds __firstlineno__, __static_attributes__)
COMPILER_NAMES = frozenset({"__module__", "__qualname__", "__annotations__", "__classcell__", "__doc__",
                            "__firstlineno__", "__static_attributes__"})
DATA = frozenset({"__slots__", "__match_args__"})  # dunder data a class body may bind (checked in make)


class ProgramClass(type):
    """The type of every class a program defines (records.build_class makes them); a class hashes
    by serial_hash (type's hash is its address)."""

    def __repr__(cls):
        return f"<class '__main__.{type.__getattribute__(cls, '__qualname__')}'>"

    def __hash__(cls) -> int:
        return serial_hash(cls)


def check_names(name: str, namespace: Any) -> None:
    """What a class body of the program may bind: DEFINABLE dunders, the compiler's, DATA."""
    for key in namespace:
        if key[:2] == "__" and key not in DEFINABLE and key not in COMPILER_NAMES and key not in DATA:
            raise Forbidden(f"class {name}: defining {key} is not allowed (it changes how Python treats the object)")
    slots = namespace.get("__slots__", ())
    for slot in [slots] if type(slots) is str else slots if type(slots) in (tuple, list) else [None]:
        if type(slot) is not str or (slot[:2] == "__" and slot[-2:] == "__"):
            raise Forbidden(f"class {name}: __slots__ must be a str, tuple or list of names, none of them a dunder "
                            f"(not {slot!r:.40})")


class ProgramEnumType(enum.EnumType):
    """The type of every enum a program defines (enums.py's bases): EnumType, after check_names."""

    def __new__(metacls, cls: str, bases: tuple[type, ...], classdict: Any, **kwds: Any) -> Any:
        check_names(cls, classdict)
        return super().__new__(metacls, cls, bases, classdict, **kwds)


METACLASSES = frozenset({ProgramClass, ProgramEnumType})  # the types of the program's classes


def is_program_object(obj) -> bool:
    """An instance of a program's class, or such a class."""
    return type(type(obj)) in METACLASSES or type(obj) in METACLASSES


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


_NAMED_TYPES = frozenset({bool, float, complex, list, tuple, dict, set, frozenset, bytes, range, slice, type(None),
                          collections.Counter, collections.deque, collections.defaultdict, collections.OrderedDict,
                          collections.ChainMap})


def type_of(*args: Any) -> Any:
    """`type(x)`: x's class where the program could name it anyway: its own classes (enums
    too), exceptions, the program's `int` and `str` for Python's, the other built-in types and
    collections' types; never a metaclass (`type(cls)`) nor an internal type, and never a new class."""
    if len(args) != 1:
        raise Forbidden("type() with three arguments makes a class outside a class statement: it is not "
                        "available in the sandbox")
    t = type(args[0])
    if t in _NAMED_TYPES or type(t) in METACLASSES or issubclass(t, BaseException):
        return t
    if t is int or t is str:
        return conversions.INT if t is int else conversions.STR
    raise Forbidden(f"type() of a {'class' if issubclass(t, type) else t.__name__} is not available in the "
                    f"sandbox (it reaches the interpreter)")


def make(name: str, bases: tuple, namespace: dict, abstract: bool = False):
    """A program class from a namespace whose names were checked (or are ours); `abstract`: made
    as ABCMeta would make it (metaclass=ABCMeta), as is any class with an abstract base (ABC)."""
    check_names(name, namespace)
    if "__hash__" not in namespace and "__eq__" not in namespace and all(
            base.__hash__ is object.__hash__ or base.__hash__ is serial_hash for base in bases):
        namespace["__hash__"] = serial_hash
    cls = ProgramClass(name, bases, namespace)
    if abstract or any(hasattr(base, "__abstractmethods__") for base in bases):
        set_abstract_methods(cls)
    return cls


def set_abstract_methods(cls: Any) -> None:
    """`__abstractmethods__` as abc.ABCMeta computes it: then `cls()` raises Python's TypeError
    ("Can't instantiate abstract class ...") while one of them is not overridden."""
    abstracts = {name for name, value in cls.__dict__.items() if getattr(value, "__isabstractmethod__", False)}
    for base in cls.__bases__:
        for name in getattr(base, "__abstractmethods__", ()):
            if getattr(getattr(cls, name, None), "__isabstractmethod__", False):
                abstracts.add(name)
    cls.__abstractmethods__ = frozenset(abstracts)


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
