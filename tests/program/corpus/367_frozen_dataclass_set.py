from dataclasses import dataclass


@dataclass(frozen=True)
class Cell:
    row: int
    col: int


wanted = [Cell(0, 0), Cell(0, 1), Cell(0, 0), Cell(1, 1)]
unique = set(wanted)
for cell in sorted(unique, key=lambda c: (c.row, c.col)):
    put(board, 'washer', 'green', cell.row, cell.col)
