"""The methods a program may call, per type (TYPE_METHODS, checked at run time against the
object's type: runtime._attr), and the checked forms of those whose result the budget must see
(CHECKED_METHODS: case mappings, paddings, join, replace, format, format_map, list.extend)."""
from __future__ import annotations

import collections

from . import budget
from .budget import INTS, checked_len, grow, too_long
from .formatting import str_format

_LIST = frozenset({"append", "extend", "insert", "pop", "index", "count", "remove", "reverse", "sort", "copy",
                   "clear"})
_DICT = frozenset({"get", "items", "keys", "values", "pop", "update", "setdefault", "copy", "clear", "popitem"})
_FROZEN = frozenset({"union", "intersection", "difference", "symmetric_difference", "issubset", "issuperset",
                     "isdisjoint", "copy"})
_SET = _FROZEN | {"add", "update", "discard", "remove", "pop", "clear", "intersection_update",
                  "difference_update", "symmetric_difference_update"}
_STR = frozenset({
    "lower", "upper", "title", "capitalize", "swapcase", "casefold", "strip", "lstrip", "rstrip", "split",
    "rsplit", "splitlines", "partition", "rpartition", "join", "replace", "startswith", "endswith", "find",
    "rfind", "index", "rindex", "count", "format", "format_map", "center", "ljust", "rjust", "zfill",
    "isdigit", "isalpha", "isalnum", "isspace", "isupper", "islower", "isnumeric", "isdecimal", "istitle",
    "removeprefix", "removesuffix"})
TYPE_METHODS: dict[type, frozenset[str]] = {  # the methods a program may call, per type (checked again at run time)
    list: _LIST, dict: _DICT, str: _STR, set: _SET, frozenset: _FROZEN,
    tuple: frozenset({"index", "count"}),
    collections.defaultdict: _DICT, collections.OrderedDict: _DICT | {"move_to_end"},
    collections.ChainMap: _DICT | {"new_child", "parents", "maps"},
    collections.Counter: _DICT | {"most_common", "elements", "subtract", "total"},
    collections.deque: frozenset({"append", "appendleft", "pop", "popleft", "extend", "extendleft", "rotate",
                                  "index", "count", "remove", "reverse", "copy", "clear", "insert"}),
}
METHODS = frozenset().union(*TYPE_METHODS.values())


def _case(method):
    def checked(s):
        bound = getattr(s, method)

        def call(*args, **kwargs):
            return checked_len(bound(*args, **kwargs))
        return call
    return checked


def _join(sep):
    def join(iterable):
        items = list(iterable)
        total = len(sep) * max(0, len(items) - 1)
        for item in items:
            if type(item) is str:
                total += len(item)
        if total > budget.LENGTH:
            too_long(total)
        return sep.join(items)
    return join


def _replace(s):
    def replace(old, new, count=-1):
        if type(old) is str and type(new) is str and len(new) > len(old):
            n = s.count(old) if old else len(s) + 1
            if type(count) is int and 0 <= count < n:
                n = count
            if len(s) + n * (len(new) - len(old)) > budget.LENGTH:
                too_long(len(s) + n * (len(new) - len(old)))
        return s.replace(old, new, count)
    return replace


def _padder(method):
    def checked(s):
        bound = getattr(s, method)

        def pad(width, *args):
            if type(width) in INTS and width > budget.LENGTH:
                too_long(width)
            return bound(width, *args)
        return pad
    return checked


def _format_method(s):
    def format_(*args, **kwargs):
        return str_format(s, args, kwargs)
    return format_


def _format_map(s):
    def format_map(mapping):
        return str_format(s, (), mapping)
    return format_map


def _extender(obj):
    def extend(items):
        grow(obj, items)
    return extend


# name -> (object -> the bound method the program gets), for methods whose result the budget
# must see; every other allowed method is the object's own
CHECKED_METHODS = {
    **{m: _case(m) for m in ("upper", "lower", "title", "capitalize", "swapcase", "casefold")},
    **{m: _padder(m) for m in ("center", "ljust", "rjust", "zfill")},
    "join": _join, "replace": _replace, "format": _format_method, "format_map": _format_map,
    "extend": _extender,
}
