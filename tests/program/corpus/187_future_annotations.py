from __future__ import annotations

def place(board: Board, cells: list[tuple[int, int]]) -> Board:
    for x, y in cells:
        put(board, 'nut', 'red', x, y)
    return board

board = place(board, [(1, 1), (1, 2)])
