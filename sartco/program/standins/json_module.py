"""The json stand-in (the authors' scorer namespace bound `json`; `import json` works too).

Only plain data: `dumps(obj, *, indent=None, sort_keys=False, separators=None, ensure_ascii=True,
skipkeys=False, allow_nan=True)`, `loads(s)` and `JSONDecodeError`. No `default`, `cls`,
`object_hook` or `parse_*` arguments: they would hand objects to program functions from inside
the encoder, or run program classes there. Before any text is made, `dumps` counts what it
would write (every value, a shared list each time it appears, each level's indent and
separators) against the length budget, so a small program cannot ask for gigabytes of text;
a value that contains itself is json's own ValueError.
"""
from __future__ import annotations

import json

from . import budget
from .budget import too_long

_SCALAR = (bool, int, float, type(None))


def _size(obj, extra: int, depth: int, active: set, total: list) -> None:
    t = type(obj)
    if t is str:
        total[0] += len(obj) + 2 + extra * depth
    elif t is int:
        total[0] += obj.bit_length() // 3 + 2 + extra * depth
    elif t in _SCALAR:
        total[0] += 5 + extra * depth
    elif t in (list, tuple, dict):
        if id(obj) in active:
            raise ValueError("Circular reference detected")
        active.add(id(obj))
        total[0] += 2 + extra * depth
        for item in (obj.items() if t is dict else obj):
            if t is dict:
                _size(item[0], extra, depth + 1, active, total)
                item = item[1]
            _size(item, extra, depth + 1, active, total)
        active.discard(id(obj))
    # any other type: json.dumps names it in its TypeError
    if total[0] > budget.LENGTH:
        too_long(total[0])


def dumps(obj, *, indent=None, sort_keys=False, separators=None, ensure_ascii=True, skipkeys=False,
          allow_nan=True):
    width = indent if type(indent) is int else len(indent) if type(indent) is str else 0
    extra = max(0, width) + sum(len(s) for s in separators if type(s) is str) if separators else max(0, width) + 2
    total = [0]
    _size(obj, extra, 0, set(), total)
    return json.dumps(obj, indent=indent, sort_keys=sort_keys, separators=separators, ensure_ascii=ensure_ascii,
                      skipkeys=skipkeys, allow_nan=allow_nan)


def loads(s):
    return json.loads(s)


MEMBERS = {"dumps": dumps, "loads": loads, "JSONDecodeError": json.JSONDecodeError}
