from __future__ import annotations
from dataclasses import dataclass

@dataclass
class Spot:
    x: int
    y: int

    def right(self) -> Spot:
        return Spot(self.x, self.y + 1)

s = Spot(4, 4)
put(board, 'washer', 'yellow', s.x, s.y)
put(board, 'washer', 'yellow', s.right().x, s.right().y)
