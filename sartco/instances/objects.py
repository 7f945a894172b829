"""Seeds -> objects -> coloured objects, by enumeration.

A seed (resources/templates/code/simple/<name>.j2) is a spatial pattern of shape slots: each
slot is a put at an offset (dx rows down, dy columns right) from the object's anchor, either
open ("any": washer, nut, screw, bridge-h, bridge-v) or fixed to one shape. Rendered with
shapes, colours and an anchor, the seed gives the object's first-order puts.

An object is a filling of a seed's open slots that
- places without error on an empty board (sartco.world.put, the one set of rules, which also
  puts nothing on a screw),
- repeats no shape among the puts anchored at one offset: no washer, nut or screw twice in
  one stack, and no bridge on a bridge of the same orientation at the same anchor. The world
  lets a bridge lie directly on a bridge of the same orientation (as the authors' simulator;
  the published object bbb stacks the second cell of a bridge-h on another bridge-h), but the
  authors' objects never repeat a piece at one anchor: 262 fillings, 68 combo names.
A colouring gives each component one of the colours such that no piece lies directly on a
piece of the same colour (checked in both cells of a bridge).
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import lru_cache

from sartco.world import BRIDGES, COLORS, LETTERS, SHAPES, Board, WorldError, put

from .templates import environment, render

ANY = "any"


@dataclass(frozen=True, slots=True)
class Seed:
    name: str                                  # "threeshapes_seed2"
    template: str                              # "code/simple/threeshapes_seed2.j2"
    slots: tuple[tuple[int, int, str], ...]    # (dx, dy, "any" | shape)
    function_form: str                         # optimal function: "offsets" | "stack"


@dataclass(frozen=True, slots=True)
class ObjectSpec:
    """One filled seed: ordered shapes with offsets from the anchor, and all its colourings."""
    seed: str
    combo: str
    shapes: tuple[str, ...]
    dxs: tuple[int, ...]
    dys: tuple[int, ...]
    cells: tuple[tuple[int, int], ...]         # covered cells relative to the anchor, row-major
    rows: int                                  # footprint (occupied rows x columns)
    cols: int
    colorings: tuple[tuple[str, ...], ...]

    def puts(self, colors, x: int, y: int) -> list[tuple[str, str, int, int]]:
        return [(s, c, x + dx, y + dy) for s, c, dx, dy in zip(self.shapes, colors, self.dxs, self.dys)]


def seed_template(name: str) -> str:
    return f"code/simple/{name}.j2"


@lru_cache(maxsize=None)
def load_seed(name: str) -> Seed:
    module = environment().get_template(seed_template(name)).module
    slots = tuple((int(dx), int(dy), str(allowed)) for dx, dy, allowed in module.slots)
    for dx, dy, allowed in slots:
        if allowed != ANY and allowed not in SHAPES:
            raise ValueError(f"seed {name}: slot shape {allowed!r} is not 'any' or one of {SHAPES}")
    return Seed(name, seed_template(name), slots, str(module.function_form))


def seed_puts(seed: Seed, shapes, colors, x: int, y: int) -> list[str]:
    """The seed template rendered: the object's first-order put lines."""
    text = render(seed.template, shapes=list(shapes), colors=list(colors), x=x, y=y)
    return [line for line in text.splitlines() if line.strip()]


def covered(shape: str, x: int, y: int) -> list[tuple[int, int]]:
    off = BRIDGES.get(shape)
    return [(x, y)] if off is None else [(x, y), (x + off[0], y + off[1])]


def _stacks(shapes, dxs, dys) -> dict[tuple[int, int], list[int]]:
    """cell -> indices of the pieces in it, bottom to top."""
    out: dict[tuple[int, int], list[int]] = {}
    for i, (s, dx, dy) in enumerate(zip(shapes, dxs, dys)):
        for cell in covered(s, dx, dy):
            out.setdefault(cell, []).append(i)
    return out


def _places(shapes, dxs, dys) -> bool:
    board = Board(max(dxs) + 2, max(dys) + 2)
    try:
        for s, dx, dy in zip(shapes, dxs, dys):
            put(board, s, COLORS[0], dx, dy)
    except WorldError:
        return False
    return True


def _no_repeated_part(shapes, dxs, dys) -> bool:
    anchored = list(zip(shapes, dxs, dys))
    return len(set(anchored)) == len(anchored)  # no shape twice at one anchor


def _colorings(n: int, stacks, colors) -> tuple[tuple[str, ...], ...]:
    pairs = {(below, above) for pieces in stacks.values() for below, above in zip(pieces, pieces[1:])}
    return tuple(c for c in itertools.product(colors, repeat=n)
                 if all(c[a] != c[b] for a, b in pairs))


def fill(seed: Seed, colors=COLORS) -> list[ObjectSpec]:
    """Every object of one seed, in the order of the shape table."""
    dxs = tuple(s[0] for s in seed.slots)
    dys = tuple(s[1] for s in seed.slots)
    options = [SHAPES if allowed == ANY else (allowed,) for _, _, allowed in seed.slots]
    out = []
    for shapes in itertools.product(*options):
        if not _places(shapes, dxs, dys):
            continue
        if not _no_repeated_part(shapes, dxs, dys):
            continue
        stacks = _stacks(shapes, dxs, dys)
        cells = tuple(sorted(stacks))
        out.append(ObjectSpec(
            seed=seed.name, combo="".join(LETTERS[s] for s in shapes), shapes=tuple(shapes),
            dxs=dxs, dys=dys, cells=cells,
            rows=max(r for r, _ in cells) + 1, cols=max(c for _, c in cells) + 1,
            colorings=_colorings(len(shapes), stacks, tuple(colors)),
        ))
    return out


@lru_cache(maxsize=None)
def enumerate_objects(seed_names: tuple[str, ...], colors: tuple[str, ...] = COLORS) -> tuple[ObjectSpec, ...]:
    """All objects of the given seeds, seed by seed."""
    return tuple(obj for name in seed_names for obj in fill(load_seed(name), colors))


def place_target(obj: ObjectSpec, colors, anchors) -> dict[str, list[list[str]]]:
    """The canonical cells of copies of a coloured object at the anchors (already known to place
    without error): the pieces appended in put order, rows then columns as keys."""
    cells: dict[tuple[int, int], list[list[str]]] = {}
    for x, y in anchors:
        for shape, color, px, py in obj.puts(colors, x, y):
            for cell in covered(shape, px, py):
                cells.setdefault(cell, []).append([shape, color])
    return {f"{r}:{c}": cells[(r, c)] for r, c in sorted(cells)}
