from typing import NamedTuple


class Move(NamedTuple):
    shape: str
    color: str
    x: int
    y: int

    @property
    def pos(self) -> tuple[int, int]:
        return (self.x, self.y)


moves = [Move("washer", "red", 1, 1), Move("nut", "red", 1, 1)]
for m in moves:
    put(board, m.shape, m.color, *m.pos)
put(board, "screw", "blue", *moves[0]._replace(x=4).pos)
