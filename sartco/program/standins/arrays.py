"""The numpy stand-in's arrays: the subset models use for coordinates, with numpy's semantics.

`ndarray` holds a flat list of Python numbers and a shape. Elementwise `+ - * / // % **`, unary
`-`/`abs`, comparisons (to bool arrays) with scalars and arrays (numpy's broadcasting), `shape`,
`ndim`, `size`, `len`, `T`, `reshape` (-1 too), `flatten`/`ravel`, `tolist`, `copy`, `astype`,
`sum`/`min`/`max`/`any`/`all`/`mean` (whole array), indexing by ints, slices and tuples of them
(`a[i, j]`, `a[1:, ::2]`), a bool mask, item and slice assignment, iteration (sub-arrays, or
numbers for a 1-D array), `in`. Every array is within the length budget.
Difference from numpy, by choice: items are Python ints, floats and bools, not numpy scalars
(`np.int64` is not `int` in numpy); `put` accepts them as the authors' simulator accepted numpy's
integers (it indexed a numpy board with them), and int arithmetic does not wrap at 64 bits.
"""
from __future__ import annotations

import itertools
import operator

from . import budget
from .budget import too_long
from .conversions import INT

ARRAY_NAMES = frozenset({"shape", "ndim", "size", "T", "reshape", "flatten", "ravel", "tolist", "copy", "astype",
                         "sum", "min", "max", "any", "all", "mean", "dtype"})


def _count(shape) -> int:
    n = 1
    for d in shape:
        n *= d
    if n > budget.LENGTH:
        too_long(n)
    return n


def _kind(items) -> type:
    kinds = set(map(type, items))
    if float in kinds:
        return float
    if kinds and kinds <= {bool}:
        return bool
    return int


def _strides(shape: tuple) -> tuple:
    return tuple(_count(shape[i + 1:]) for i in range(len(shape)))


class ndarray:  # numpy's name
    """Items of `base` (a flat list) at offset + sum(index * stride): indexing by ints and
    slices and `.T` give views of the same base, as numpy's basic indexing does."""

    __slots__ = ("base", "shape", "offset", "strides", "kind")

    def __init__(self, data: list, shape: tuple, offset: int = 0, strides: tuple | None = None):
        if type(data) is not list or type(shape) is not tuple:
            raise TypeError("np.ndarray(...) is not available in the sandbox: make arrays with np.array, np.zeros, ...")
        self.base, self.shape, self.offset = data, shape, offset
        self.strides = _strides(shape) if strides is None else strides
        self.kind = None  # the item type assignments convert to, found at the first one

    @property
    def data(self) -> list:
        """The items in order (the base itself when this array is all of it, in order)."""
        if self.offset == 0 and self.strides == _strides(self.shape) and len(self.base) == _count(self.shape):
            return self.base
        return [self.base[p] for p in self.positions()]

    def positions(self) -> list:
        _count(self.shape)
        out = [self.offset]
        for d, s in zip(self.shape, self.strides):
            out = [p + i * s for p in out for i in range(d)]
        return out

    ndim = property(lambda self: len(self.shape))
    size = property(lambda self: _count(self.shape))
    dtype = property(lambda self: {float: "float64", bool: "bool"}.get(_kind(self.data), "int64"))

    @property
    def T(self):  # numpy's name
        return ndarray(self.base, self.shape[::-1], self.offset, self.strides[::-1])

    def tolist(self):
        data = self.data

        def nest(start, dims):
            if not dims:
                return data[start]
            step = _count(dims[1:])
            return [nest(start + i * step, dims[1:]) for i in range(dims[0])]
        return nest(0, self.shape) if self.shape else data[0]

    def copy(self):
        return ndarray(list(self.data), self.shape)

    def astype(self, dtype):
        return ndarray([_cast(dtype)(x) for x in self.data], self.shape)

    def reshape(self, *shape):
        shape = tuple(shape[0]) if len(shape) == 1 and not isinstance(shape[0], int) else shape
        if -1 in shape:
            known = _count(d for d in shape if d != -1) or 1
            shape = tuple(self.size // known if d == -1 else d for d in shape)
        if _count(shape) != self.size:
            raise ValueError(f"cannot reshape array of size {self.size} into shape {shape}")
        return ndarray(self.data, tuple(shape))  # a view when this array is all of its base, as in numpy

    def flatten(self):
        return ndarray(list(self.data), (self.size,))

    ravel = flatten

    def sum(self):
        return sum(self.data)

    def min(self):
        return min(self.data)

    def max(self):
        return max(self.data)

    def any(self):
        return any(self.data)

    def all(self):
        return all(self.data)

    def mean(self):
        return sum(self.data) / len(self.data)

    def __len__(self):
        if not self.shape:
            raise TypeError("len() of unsized object")
        return self.shape[0]

    def __iter__(self):
        if len(self.shape) == 1:
            return iter(self.data)
        return (self[i] for i in range(self.shape[0]))

    def __contains__(self, value):
        return any(x == value for x in self.data)

    def __bool__(self):
        if self.size != 1:
            raise ValueError("The truth value of an array with more than one element is ambiguous. "
                             "Use a.any() or a.all()")
        return bool(self.data[0])

    def __repr__(self):
        return f"array({self.tolist()!r})"

    def __str__(self):
        return str(self.tolist()).replace(",", "")

    def __getitem__(self, key):
        if isinstance(key, ndarray) and _kind(key.data) is bool:  # a mask: a copy, as in numpy
            return ndarray([x for x, keep in zip(self.data, key.data) if keep], (sum(key.data),))
        view = _view(self, key)
        return self.base[view.offset] if not view.shape else view

    def __setitem__(self, key, value):
        if isinstance(key, ndarray) and _kind(key.data) is bool:
            positions = [p for p, keep in zip(self.positions(), key.data) if keep]
            shape = (len(positions),)
        else:
            view = _view(self, key)
            positions, shape = view.positions(), view.shape
        values = _broadcast_to(value, shape, len(positions))
        if self.kind is None:
            data = self.base
            self.kind = _kind(data) if all(type(x) in (int, float, bool) for x in data) else (lambda x: x)
        for p, v in zip(positions, values):
            self.base[p] = self.kind(v)

    def __neg__(self):
        return ndarray([-x for x in self.data], self.shape)

    def __abs__(self):
        return ndarray([abs(x) for x in self.data], self.shape)


_DTYPES = {"int": int, "int64": int, "int32": int, "float": float, "float64": float, "float32": float, "bool": bool}


def _cast(dtype):
    if isinstance(dtype, str) and dtype in _DTYPES:
        return _DTYPES[dtype]
    if dtype is float or dtype is bool or dtype is int:
        return dtype
    if dtype is INT:  # the program's int
        return int
    raise TypeError(f"dtype {dtype!r:.40} is not available in the sandbox (int, float, bool)")


def _view(a: ndarray, key) -> ndarray:
    """numpy's basic indexing: ints and slices, per axis, as a view of a's base."""
    keys = key if type(key) is tuple else (key,)
    if len(keys) > len(a.shape):
        raise IndexError(f"too many indices for array: array is {len(a.shape)}-dimensional, but {len(keys)} were indexed")
    offset, shape, strides = a.offset, [], []
    for axis, (d, s) in enumerate(zip(a.shape, a.strides)):
        k = keys[axis] if axis < len(keys) else slice(None)
        if type(k) is slice:
            r = range(d)[k]
            offset += (r.start if len(r) else 0) * s
            shape.append(len(r))
            strides.append(r.step * s)
        elif isinstance(k, int) and type(k) is not bool:
            if not -d <= k < d:
                raise IndexError(f"index {k} is out of bounds for axis {axis} with size {d}")
            offset += (k % d) * s
        else:
            raise IndexError("only integers, slices (`:`) and boolean masks are valid indices in the sandbox")
    return ndarray(a.base, tuple(shape), offset, tuple(strides))


def _broadcast_to(value, shape: tuple, n: int) -> list:
    if isinstance(value, (int, float)):
        return [value] * n
    source = value if isinstance(value, ndarray) else array(value)
    return _pair(source, ndarray([0] * n, shape), lambda a, b: a)[0].data


def _pair(a, b, op):
    """op elementwise over a and b (arrays or scalars), with numpy's broadcasting."""
    a = a if isinstance(a, ndarray) else array(a)
    b = b if isinstance(b, ndarray) else array(b)
    n = max(a.ndim, b.ndim)
    sa, sb = (1,) * (n - a.ndim) + a.shape, (1,) * (n - b.ndim) + b.shape
    shape = []
    for x, y in zip(sa, sb):
        if x != y and 1 not in (x, y):
            raise ValueError(f"operands could not be broadcast together with shapes {a.shape} {b.shape}")
        shape.append(max(x, y) if 0 not in (x, y) else 0)
    _count(shape)
    if sa == sb:
        return (ndarray([op(x, y) for x, y in zip(a.data, b.data)], tuple(shape)),)
    da, db = a.data, b.data
    data = [op(da[_flat(index, sa)], db[_flat(index, sb)]) for index in itertools.product(*map(range, shape))]
    return (ndarray(data, tuple(shape)),)


def _flat(index, shape) -> int:
    p = 0
    for i, d in zip(index, shape):
        p = p * d + (i if d > 1 else 0)
    return p


def _binary(op, reflected=False):
    def method(self, other):
        if not isinstance(other, (int, float, list, tuple, ndarray)):
            return NotImplemented
        return _pair(other, self, op)[0] if reflected else _pair(self, other, op)[0]
    return method


_OPS = {"add": budget.add, "sub": operator.sub, "mul": budget.mul, "truediv": operator.truediv,
        "floordiv": operator.floordiv, "mod": operator.mod, "pow": budget.power}
for _name, _op in _OPS.items():
    setattr(ndarray, f"__{_name}__", _binary(_op))
    setattr(ndarray, f"__r{_name}__", _binary(_op, reflected=True))
for _name in ("eq", "ne", "lt", "le", "gt", "ge"):
    setattr(ndarray, f"__{_name}__", _binary(getattr(operator, _name)))
ndarray.__hash__ = None


def array(obj, dtype=None):
    """np.array / np.asarray: nested lists, tuples, ranges and arrays of numbers."""
    if isinstance(obj, ndarray):
        return obj.astype(dtype) if dtype is not None else obj.copy()
    shape, data = [], []

    def walk(x, depth):
        if isinstance(x, (list, tuple, range, ndarray)):
            items = x.tolist() if isinstance(x, ndarray) else x
            if depth == len(shape) and len(data) == 0:
                shape.append(len(items))
            elif depth >= len(shape) or shape[depth] != len(items):
                raise ValueError("setting an array element with a sequence: the nested lists differ in length")
            if len(data) + len(items) > budget.LENGTH:
                too_long(len(data) + len(items))
            for item in items:
                walk(item, depth + 1)
        else:
            if depth != len(shape):
                raise ValueError("setting an array element with a sequence: the nested lists differ in length")
            data.append(x)
    walk(obj, 0)
    if dtype is None and not all(type(x) in (int, float, bool) for x in data):
        return ndarray(data, tuple(shape))  # e.g. strings: kept as they are
    kind = _cast(dtype) if dtype is not None else _kind(data)
    return ndarray([kind(x) for x in data], tuple(shape))
