"""Arrangements of regular boards: a Jinja2 template that repeats an object function over the
board (resources/templates/code/regular/<name>.j2) and its instruction template
(resources/templates/instructions/regular/regular_template<N>.j2).

Where an arrangement puts the object is found by running its rendered code with a stand-in
object function that only records the anchors; whether the board builds is decided by the
world's rules (sartco.world.put) on those anchors. Both depend on the object's shapes and
cells only, not on its colours.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from sartco.world import COLORS, Board, WorldError, put

from .objects import ObjectSpec
from .templates import render


@dataclass(frozen=True, slots=True)
class ArrangementTemplates:
    """The two templates of one regular-board arrangement: its repetition code and its instruction."""
    name: str                      # "regular_seed12"
    code_template: str             # "code/regular/regular_seed12.j2"
    instruction_template: str      # "instructions/regular/regular_template12.j2"


def arrangement(name: str) -> ArrangementTemplates:
    number = name.removeprefix("regular_seed")
    return ArrangementTemplates(name, f"code/regular/{name}.j2", f"instructions/regular/regular_template{number}.j2")


def output_code(arr: ArrangementTemplates, name: str, colors, obj: ObjectSpec) -> str:
    """The repetition code: what the model writes, given the object function."""
    return render(arr.code_template, name=name, colors=list(colors), rows=obj.rows,
                  cols=obj.cols, cells=[list(c) for c in obj.cells]).strip("\n")


def instruction(arr: ArrangementTemplates, name: str, colors, obj: ObjectSpec) -> str:
    return " ".join(render(arr.instruction_template, name=name, colors=list(colors),
                           rows=obj.rows, cols=obj.cols).split())


@lru_cache(maxsize=None)
def anchors(arr_name: str, obj: ObjectSpec) -> tuple[tuple[int, int], ...] | None:
    """Where the arrangement places the object, or None when the board does not build."""
    arr = arrangement(arr_name)
    code = output_code(arr, "obj", [COLORS[0]] * len(obj.shapes), obj)
    found: list[tuple[int, int]] = []

    def record(board, colors, x, y):
        found.append((x, y))

    exec(compile(code, arr.code_template, "exec"), {"obj": record, "board": None})
    board = Board()
    seen: set[tuple[int, int]] = set()
    try:
        for x, y in found:
            for shape, color, px, py in obj.puts([COLORS[0]] * len(obj.shapes), x, y):
                put(board, shape, color, px, py)
            cells = {(x + dx, y + dy) for dx, dy in obj.cells}
            if cells & seen:
                # copies stacked on copies: the colour rule would need the whole board
                raise NotImplementedError(f"{arr_name} stacks copies of {obj.combo}; not supported")
            seen |= cells
    except WorldError:
        return None
    return tuple(found)
