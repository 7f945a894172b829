from typing import Final, Literal

ROWS: Final = 8
Shape = Literal["washer", "nut", "screw"]


def place(shape: Shape, color: str, x: int, y: int) -> None:
    put(board, shape, color, x, y)


for y in range(0, ROWS, 2):
    place("washer", "red", 1, y)
