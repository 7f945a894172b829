from dataclasses import dataclass, fields


@dataclass(slots=True, kw_only=True)
class Piece:
    shape: str
    color: str
    x: int = 0
    y: int = 0


pieces = [Piece(shape='nut', color='red', x=2, y=3), Piece(shape='screw', color='blue', y=5)]
names = [f.name for f in fields(Piece)]
for p in pieces:
    put(board, p.shape, p.color, p.x, p.y)
put(board, 'washer', 'yellow', len(names), 0)
