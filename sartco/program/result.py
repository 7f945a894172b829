"""The result of a run, checked before it leaves the worker: the board must hold exactly what
its puts placed.

A board records its puts (Board.log); the result is that log replayed by `put` on a fresh board
of the same size, so the cells that leave the worker are built from the world's vocabulary only
(exact str shapes and colours, stacks of at most 4 legal pieces, cells inside the board). When
the board's own storage differs from the replay (a program reached it some way: a leak of the
storage is a sandbox bug, and this check is the last line), the verdict is `forbidden`, "the
board was changed outside put", with the cells that put placed. The comparison reads types
before values, so nothing a program stored there runs (a str subclass may answer any ==).
"""
from __future__ import annotations

import gc

from sartco.world import WorldError
from sartco.world.rules import replay

FORGED = "the board was changed outside put"


def board_result(board) -> tuple[dict, int, str | None]:
    """(cells, puts, problem): what `put` placed on `board`, and None when its storage holds
    exactly that, else the one-line reason (FORGED ...). The cyclic collector is off meanwhile:
    this work makes no cycles, and a collection here would free a cycle the program left behind
    before the worker's retirement check (worker.py) sees the memory it held."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        try:
            fresh = replay(board)
        except (WorldError, TypeError, ValueError):  # a log that put did not write
            return {}, 0, f"{FORGED} (its log of puts is not one that put wrote)"
        if board.puts != fresh.puts or not _same(board.stacks, fresh.stacks):
            return fresh.cells(), fresh.puts, FORGED
        return fresh.cells(), fresh.puts, None
    finally:
        if collecting:
            gc.enable()


def _same(stacks, built: list) -> bool:
    """`stacks` is a list of lists of (str, str) pieces, equal to `built` (exact types first)."""
    if type(stacks) is not list or len(stacks) != len(built):
        return False
    for stack, want in zip(stacks, built):
        if type(stack) is not list or len(stack) != len(want):
            return False
        for piece, good in zip(stack, want):
            if type(piece) is not tuple or len(piece) != 2 or type(piece[0]) is not str \
                    or type(piece[1]) is not str or piece != good:
                return False
    return True
