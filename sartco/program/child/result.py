"""The result of a run, checked before it leaves the worker: the board must hold exactly what
its puts placed.

A board records its puts (Board.log); the result is that log replayed by `put` on a fresh board
of the same size, so the cells that leave the worker are built from the world's vocabulary only
(exact str shapes and colours, stacks of at most 4 legal pieces, cells inside the board). When
the board's own storage differs from the replay (a program reached it some way: a leak of the
storage is a sandbox bug, and this check is the last line), the verdict is `forbidden`, "the
board was changed outside put", with the cells that put placed. The comparison is by
identity, so nothing a program stored there runs (a str subclass may answer any ==).
"""
from __future__ import annotations

import gc
from itertools import chain
from operator import is_

from sartco.world import Board, WorldError
from sartco.world.board import Cells
from sartco.world.rules import replay

FORGED = "the board was changed outside put"


def board_result(board: Board) -> tuple[Cells, int, str | None]:
    """(cells, puts, problem): what `put` placed on `board`, and None when its storage holds
    exactly that, else the one-line reason (FORGED ...)."""
    fresh, problem = checked(board)
    return ({}, 0, problem) if fresh is None else (fresh.cells(), fresh.puts, problem)


def checked(board: Board) -> tuple[Board | None, str | None]:
    """(the board that put placed, problem): `board`'s log replayed on a fresh board, and None
    when `board`'s storage holds exactly that, else the one-line reason (FORGED ...); no board
    when the log is not one that put wrote. The cyclic collector is off meanwhile: this work
    makes no cycles."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        try:
            fresh = replay(board)
        except (WorldError, TypeError, ValueError):  # a log that put did not write
            return None, f"{FORGED} (its log of puts is not one that put wrote)"
        if board.puts != fresh.puts or not _same(board.stacks, fresh.stacks):
            return fresh, FORGED
        return fresh, None
    finally:
        if collecting:
            gc.enable()


def _same(stacks: object, built: list[list[tuple[str, str]]]) -> bool:
    """`stacks` is a list of lists holding the very piece objects of `built` (the replay puts
    the log's own tuples): compared by identity, in C, so nothing a program stored there runs
    (a str subclass may answer any ==)."""
    if type(stacks) is not list or len(stacks) != len(built) or set(map(type, stacks)) - _LIST:
        return False
    return [*map(len, stacks)] == [*map(len, built)] and all(
        map(is_, chain.from_iterable(stacks), chain.from_iterable(built)))


_LIST = {list}
