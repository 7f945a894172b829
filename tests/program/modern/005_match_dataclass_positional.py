from dataclasses import dataclass


@dataclass
class Piece:
    shape: str
    color: str
    x: int
    y: int


pieces = [Piece("washer", "red", 0, 0), Piece("nut", "blue", 1, 1), Piece("screw", "green", 7, 7)]

for p in pieces:
    match p:
        case Piece("screw", color, x, y):
            put(board, "screw", color, x, y)
        case Piece(shape, color, x, y) if x == y:
            put(board, shape, color, x, y)
