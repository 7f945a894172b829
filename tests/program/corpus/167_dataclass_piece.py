from dataclasses import dataclass

@dataclass
class Piece:
    shape: str
    color: str
    x: int
    y: int

pieces = [Piece('washer', 'red', 5, 5), Piece('nut', 'green', 5, 5), Piece('screw', 'blue', 5, 5)]
for p in pieces:
    put(board, p.shape, p.color, p.x, p.y)
