"""numpy's functions in the stand-in (arrays.py has the arrays): `array`/`asarray`, `zeros`,
`ones`, `full`, `arange`, `linspace` (numpy's formula: start + i * step, the last item stop),
`ndindex`, `ndenumerate`, `where` (1 and 3 arguments), `nonzero`, `meshgrid`, `argwhere`, `unique`, `concatenate` (axis 0),
`zeros_like`/`ones_like`, `sum`/`min`/`max`/`any`/`all`/`mean` of a whole array,
and `sqrt`, `floor`, `ceil`, `abs` elementwise. Every result is within the length budget.
"""
from __future__ import annotations

import itertools
import math

from . import budget
from .arrays import _cast, _count, _pair, array, ndarray
from .budget import too_long

def _shape(shape) -> tuple:
    dims = (shape,) if isinstance(shape, int) else tuple(shape)
    if any(type(d) is not int or d < 0 for d in dims):
        raise ValueError(f"a shape is non-negative integers, got {shape!r:.40}")
    _count(dims)
    return dims


def full(shape, fill_value, dtype=None):
    dims = _shape(shape)
    value = fill_value if dtype is None else _cast(dtype)(fill_value)
    return ndarray([value] * _count(dims), dims)


def zeros(shape, dtype=float):
    return full(shape, 0, dtype)


def ones(shape, dtype=float):
    return full(shape, 1, dtype)


def arange(*args, dtype=None):
    if all(type(a) is int for a in args):
        data = list(budget.checked_range(*args))
    else:
        start, stop, step = (0, args[0], 1) if len(args) == 1 else (*args, 1)[:3]
        n = max(0, -(-(stop - start) // step))
        if n > budget.LENGTH:
            too_long(n)
        data = [start + i * step for i in range(int(n))]
    return ndarray([_cast(dtype)(x) for x in data] if dtype is not None else data, (len(data),))


def linspace(start, stop, num=50, endpoint=True, dtype=None):
    if type(num) is not int or num < 0:
        raise ValueError(f"Number of samples, {num!r:.40}, must be non-negative.")
    if num > budget.LENGTH:
        too_long(num)
    div = (num - 1) if endpoint else num
    step = (stop - start) / div if div > 0 else float("nan")
    data = [i * step + start if div > 0 else float(start) for i in range(num)]
    if endpoint and num > 1:
        data[-1] = float(stop)
    return ndarray([_cast(dtype)(x) for x in data] if dtype is not None else data, (num,))


def ndindex(*shape):
    dims = _shape(shape[0] if len(shape) == 1 and not isinstance(shape[0], int) else shape)
    return itertools.product(*map(range, dims))


def ndenumerate(a):
    """((index, ...), item) for every item of `a`, in order."""
    a = a if isinstance(a, ndarray) else array(a)
    return zip(itertools.product(*map(range, a.shape)), a.data)


def nonzero(a):
    """The indices of the items that are not zero, one array per axis (np.where of one argument)."""
    return where(a)


def where(condition, x=None, y=None):
    cond = condition if isinstance(condition, ndarray) else array(condition)
    if x is None and y is None:
        picked = [i for i, c in enumerate(cond.data) if c]
        strides = [_count(cond.shape[k + 1:]) for k in range(cond.ndim)]
        return tuple(ndarray([p // s % d for p in picked], (len(picked),)) for s, d in zip(strides, cond.shape))
    if x is None or y is None:
        raise ValueError("either both or neither of x and y should be given")
    chosen = _pair(cond, x, lambda c, a: (c, a))[0]
    return _pair(chosen, y, lambda ca, b: ca[1] if ca[0] else b)[0]


def _whole(name):
    def reduce(a, axis=None):
        if axis is not None:
            raise ValueError(f"np.{name} with an axis is not available in the sandbox")
        return getattr(a if isinstance(a, ndarray) else array(a), name)()
    return reduce


def _elementwise(function, name):
    def apply(x):
        if isinstance(x, (ndarray, list, tuple)):
            a = x if isinstance(x, ndarray) else array(x)
            return ndarray([function(v) for v in a.data], a.shape)
        return function(x)
    apply.__name__ = name
    return apply


def meshgrid(x, y, indexing="xy"):
    xs, ys = array(x).data, array(y).data
    if indexing == "ij":
        return ndarray([a for a in xs for _ in ys], (len(xs), len(ys))), ndarray([b for _ in xs for b in ys], (len(xs), len(ys)))
    return ndarray([a for _ in ys for a in xs], (len(ys), len(xs))), ndarray([b for b in ys for _ in xs], (len(ys), len(xs)))


def argwhere(a):
    found = where(a)
    return ndarray([int(axis.data[i]) for i in range(len(found[0].data)) for axis in found], (len(found[0].data), len(found)))


def unique(a):
    items = sorted(set(array(a).data))
    return ndarray(items, (len(items),))


def concatenate(arrays, axis=0):
    parts = [array(a) for a in arrays]
    if axis != 0 or len({p.shape[1:] for p in parts}) > 1:
        raise ValueError("np.concatenate in the sandbox joins arrays of the same shape along axis 0")
    data = [x for p in parts for x in p.data]
    _count((len(data),))
    return ndarray(data, (sum(p.shape[0] for p in parts), *parts[0].shape[1:]))


def _like(value):
    def like(a, dtype=None):
        source = array(a)
        return full(source.shape, value, dtype if dtype is not None else type(_kind_of(source)(value)))
    return like


def _kind_of(a):
    return float if any(type(x) is float for x in a.data) else int


MEMBERS = {
    "ndarray": ndarray, "array": array, "asarray": array, "zeros": zeros, "ones": ones, "full": full,
    "arange": arange, "linspace": linspace, "ndindex": ndindex, "ndenumerate": ndenumerate, "where": where,
    "nonzero": nonzero,
    **{name: _whole(name) for name in ("sum", "min", "max", "any", "all", "mean")},
    "amin": _whole("min"), "amax": _whole("max"), "meshgrid": meshgrid, "argwhere": argwhere, "unique": unique,
    "concatenate": concatenate, "zeros_like": _like(0), "ones_like": _like(1),
    "sqrt": _elementwise(math.sqrt, "sqrt"), "abs": _elementwise(abs, "abs"),
    "floor": _elementwise(lambda v: float(math.floor(v)), "floor"),
    "ceil": _elementwise(lambda v: float(math.ceil(v)), "ceil"),
}
