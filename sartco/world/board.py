"""The board and its one canonical form: {"row:col": [[shape, color], ...]} bottom to top."""
from __future__ import annotations

import re
from itertools import compress
from typing import NoReturn, SupportsIndex

from .components import DEFAULT_COLS, DEFAULT_ROWS
from .error_codes import ErrorCode, WorldError

Cells = dict[str, list[list[str]]]
MAX_SIDE = 64
KEY = re.compile(r"\d+:\d+")  # a cell key, "row:col", as the canonical form writes it
_KEYS: dict[int, tuple[str, ...]] = {}  # cols -> the "row:col" keys in row-major order, made once per width


def _keys(cols: int) -> tuple[str, ...]:
    keys = _KEYS.get(cols)
    if keys is None:
        keys = _KEYS[cols] = tuple(f"{r}:{c}" for r in range(MAX_SIDE) for c in range(cols))
    return keys


class Board:
    """A rows x cols grid of stacks, kept row-major in one flat list (cell (x, y) is
    stacks[x * cols + y]: one list to make per board, not one per row). A bridge is listed in
    both of its cells. `log` lists the puts that built it, ((shape, colour), x, y) in order: the
    sandbox replays it to prove that nothing but `put` changed the board (program/result.py).

    Only `put` changes a board: a copy (copy.copy, copy.deepcopy) is an independent board with
    its own storage and log, and a board refuses to be reduced or pickled (the protocol hands
    out a board's storage)."""

    __slots__ = ("rows", "cols", "stacks", "puts", "log")

    def __init__(self, rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS):
        if not (type(rows) is int and type(cols) is int and 1 <= rows <= MAX_SIDE and 1 <= cols <= MAX_SIDE):
            _bad_size(rows, cols)
        self.rows = rows
        self.cols = cols
        self.stacks: list[list[tuple[str, str]]] = [[] for _ in range(rows * cols)]
        self.puts = 0
        self.log: list[tuple[tuple[str, str], int, int]] = []

    def __copy__(self) -> "Board":
        twin = Board(self.rows, self.cols)
        twin.stacks = [stack.copy() for stack in self.stacks]  # pieces are tuples of str: shared safely
        twin.puts, twin.log = self.puts, self.log.copy()
        return twin

    def __deepcopy__(self, memo: dict[int, object]) -> "Board":
        return self.__copy__()  # the memo never sees the storage

    def __reduce_ex__(self, protocol: SupportsIndex) -> NoReturn:
        raise WorldError(ErrorCode.FORBIDDEN, "a board cannot be reduced or pickled: only put changes a board")

    def __reduce__(self) -> NoReturn:
        self.__reduce_ex__(0)

    def __repr__(self) -> str:
        return f"<board {self.rows}x{self.cols}, {self.puts} pieces>"

    def cells(self) -> Cells:
        """The canonical form, keys in row-major order, empty cells left out."""
        stacks = self.stacks
        return {key: [*map(list, stack)] for key, stack in compress(zip(_keys(self.cols), stacks), stacks)}


def _bad_size(rows: object, cols: object) -> None:
    for name, value in (("rows", rows), ("cols", cols)):
        if type(value) is not int:
            raise WorldError(ErrorCode.TYPE_ERROR, f"init_board: {name} must be an integer, got {type(value).__name__}")
        if not 1 <= value <= MAX_SIDE:
            raise WorldError(ErrorCode.DIMENSIONS_MISMATCH, f"init_board: {name}={value} is outside 1..{MAX_SIDE}")


def parse_key(key: str) -> tuple[int, int]:
    row, _, col = key.partition(":")
    return int(row), int(col)

