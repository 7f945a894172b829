"""Generated board records (sartco.dataset.BoardRecord, without id and split until generate adds
them): the code in the paper's styles and the template instructions of one board, all rendered
from resources/templates."""
from __future__ import annotations

from typing import Any

from sartco.dataset import REGULAR_SIMPLE, SIMPLE
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS

from .arrangements import arrangement, instruction, output_code
from .objects import ObjectSpec, load_seed, place_target, seed_puts
from .templates import render

ORIENTATION = {"bridge-h": "horizontal", "bridge-v": "vertical"}
QUADRANT_ORIGIN = {"tl": (0, 0), "tr": (0, 4), "bl": (4, 0), "br": (4, 4)}


def anchors_in_quadrant(obj: ObjectSpec, quadrant: str) -> list[tuple[int, int]]:
    """Anchors inside the quadrant from which the whole object lies on the board."""
    rows, cols = DEFAULT_ROWS, DEFAULT_COLS
    r0, c0 = QUADRANT_ORIGIN[quadrant]
    return [(x, y) for x in range(r0, r0 + rows // 2) for y in range(c0, c0 + cols // 2)
            if x + obj.rows <= rows and y + obj.cols <= cols]


def optimal_function(obj: ObjectSpec) -> str:
    return render("code/optimal_function.j2", name=obj.combo, shapes=list(obj.shapes),
                  dxs=list(obj.dxs), dys=list(obj.dys), form=load_seed(obj.seed).function_form).strip("\n")


def _program(function: str, usage: str) -> str:
    return render("code/program.j2", function=function, usage=usage, rows=DEFAULT_ROWS, cols=DEFAULT_COLS).strip("\n")


def simple_record(obj: ObjectSpec, colors, quadrant: str, x: int, y: int) -> dict[str, Any]:
    seed = load_seed(obj.seed)
    colors = list(colors)
    puts = [{"shape": s, "color": c, "x": px, "y": py} for s, c, px, py in obj.puts(colors, x, y)]
    steps = seed_puts(seed, obj.shapes, colors, x, y)
    xs, ys = [p["x"] for p in puts], [p["y"] for p in puts]
    name = obj.combo
    seq_function = render("code/sequence_function.j2", name=name, puts=puts).strip("\n")
    seq_usage = render("code/sequence_usage.j2", name=name, colors=colors, xs=xs, ys=ys).strip()
    opt_function = optimal_function(obj)
    opt_usage = render("code/optimal_usage.j2", name=name, colors=colors, x=x, y=y).strip()
    return {
        "board_type": SIMPLE.board, "object_type": SIMPLE.object,
        "combo_name": name, "shapes": list(obj.shapes), "colors": colors,
        "quadrant": quadrant, "rows": DEFAULT_ROWS, "cols": DEFAULT_COLS,
        "seed": obj.seed, "arrangement": None,
        "placement": {"x": xs, "y": ys, "orientations": [ORIENTATION.get(s) for s in obj.shapes]},
        "occupied_rows": None, "occupied_cols": None,
        "target": place_target(obj, colors, [(x, y)]),
        "code": {
            "first_order": {"steps": steps,
                            "total_code": render("code/first_order.j2", steps=steps, rows=DEFAULT_ROWS,
                                                 cols=DEFAULT_COLS).strip("\n")},
            "sequence_function": {"function": seq_function, "usage": seq_usage,
                                  "total_code": _program(seq_function, seq_usage)},
            "optimal_function": {"function": opt_function, "usage": opt_usage,
                                 "total_code": _program(opt_function, opt_usage)},
        },
        "instructions": {"template": {
            "single_turn": render("instructions/simple/singleturn.j2", name=name, puts=puts).strip(),
            "multi_turn": [render("instructions/simple/multiturn.j2", name=name, puts=puts, step=i).strip()
                           for i in range(len(puts))],
        }},
        "provenance": {"source": "generated"},
    }


def regular_record(obj: ObjectSpec, colors, arrangement_name: str, anchors, object_type: str) -> dict[str, Any]:
    arr = arrangement(arrangement_name)
    colors = list(colors)
    name = obj.combo
    function = optimal_function(obj)
    output = output_code(arr, name, colors, obj)
    return {
        "board_type": REGULAR_SIMPLE.board, "object_type": object_type,
        "combo_name": name, "shapes": list(obj.shapes), "colors": colors,
        "quadrant": "tl", "rows": DEFAULT_ROWS, "cols": DEFAULT_COLS,
        "seed": obj.seed, "arrangement": arrangement_name,
        "placement": None,
        "occupied_rows": obj.rows, "occupied_cols": obj.cols,
        "target": place_target(obj, colors, anchors),
        "code": {"repetition": {"function": function, "output": output, "total_code": _program(function, output)}},
        "instructions": {"template": {"regular": instruction(arr, name, colors, obj)}},
        "provenance": {"source": "generated"},
    }
