from dataclasses import dataclass


@dataclass(frozen=True)
class Pos:
    x: int
    y: int


@dataclass(frozen=True)
class Place:
    shape: str
    color: str
    at: Pos


@dataclass(frozen=True)
class Line:
    color: str
    start: Pos
    length: int


plan = [Place("washer", "red", Pos(0, 0)), Line("blue", Pos(2, 1), 4), Place("nut", "red", Pos(0, 0))]
for step in plan:
    match step:
        case Place(shape=shape, color=color, at=Pos(x=x, y=y)):
            put(board, shape, color, x, y)
        case Line(color, Pos(x, y), n):
            for dy in range(n):
                put(board, "washer", color, x, y + dy)
