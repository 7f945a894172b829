"""A built board against its target: execution success, mismatch category, cell P/R/F1.

- es is 1 only if every cell's stack equals the target's (empty cells ignored).
- category: target cells scanned in row-major order, the first differing cell decides:
  missing cell -> mismatch_location; another stack height -> mismatch_count; other shapes
  (as a multiset) -> mismatch_shape; the same shapes in another order -> mismatch_order;
  else (only colours differ) -> mismatch_color. If all target cells match, a built cell that
  the target leaves empty -> mismatch_location. Equal boards -> None.
- precision/recall/F1 over the sets of (row, col, level, shape, colour) entries, level 0 at the
  bottom (a bridge counts in both its cells). 0/0 is 1.0 only when both boards are empty
  (nothing to build, nothing built); otherwise an undefined ratio is 0.0.

`judge(ok, error, cells, target)` is the one verdict of an execution against its target (the
games' builds and `sartco execute`): the comparison of the board it built, except that a
program that did not run to the end has ES 0 and its own error as the category (P/R/F1 still
count the board it built so far).
"""
from __future__ import annotations

from dataclasses import dataclass

from sartco.world import Cells, ErrorCode, parse_key



@dataclass(frozen=True, slots=True)
class Comparison:
    """A built board against its target: execution success, mismatch category, cell P/R/F1."""

    es: int
    category: ErrorCode | None
    precision: float
    recall: float
    f1: float


Stacks = dict[str, list[tuple[str, ...]]]  # a board's cells with each piece a tuple


def _stacks(cells: Cells) -> Stacks:
    return {k: [tuple(p) for p in v] for k, v in cells.items() if v}


def _category(built: Stacks, target: Stacks) -> ErrorCode | None:
    for key in sorted(target, key=parse_key):
        want, got = target[key], built.get(key)
        if got is None:
            return ErrorCode.MISMATCH_LOCATION
        if got == want:
            continue
        if len(got) != len(want):
            return ErrorCode.MISMATCH_COUNT
        shapes_got, shapes_want = [p[0] for p in got], [p[0] for p in want]
        if sorted(shapes_got) != sorted(shapes_want):
            return ErrorCode.MISMATCH_SHAPE
        if shapes_got != shapes_want:
            return ErrorCode.MISMATCH_ORDER
        return ErrorCode.MISMATCH_COLOR
    if any(key not in target for key in built):
        return ErrorCode.MISMATCH_LOCATION
    return None


def _entries(stacks: Stacks) -> set[tuple[int | str, ...]]:
    out: set[tuple[int | str, ...]] = set()
    for key, stack in stacks.items():
        r, c = parse_key(key)
        for level, piece in enumerate(stack):
            out.add((r, c, level) + tuple(piece))
    return out


EQUAL = Comparison(1, None, 1.0, 1.0, 1.0)  # frozen: one for every exact build


def compare(built_cells: Cells, target_cells: Cells) -> Comparison:
    if built_cells == target_cells:  # the common case: category None, every entry a hit
        return EQUAL
    built, target = _stacks(built_cells), _stacks(target_cells)
    category = _category(built, target)
    b, t = _entries(built), _entries(target)
    hit = len(b & t)
    if not b and not t:
        precision = recall = f1 = 1.0
    else:
        precision = hit / len(b) if b else 0.0
        recall = hit / len(t) if t else 0.0
        f1 = 2 * precision * recall / (precision + recall) if precision + recall else 0.0
    return Comparison(int(category is None), category, precision, recall, f1)


def judge(ok: bool, error: ErrorCode | None, cells: Cells, target: Cells) -> Comparison:
    """An execution (did it run to the end, its error, the board it built) against its target."""
    cmp = compare(cells, target)
    if ok:
        return cmp
    return Comparison(0, error, cmp.precision, cmp.recall, cmp.f1)
