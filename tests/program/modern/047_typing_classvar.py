from dataclasses import dataclass, field
from typing import ClassVar


@dataclass
class Stack:
    MAX: ClassVar[int] = 3
    x: int
    y: int
    pieces: list = field(default_factory=list)

    def add(self, shape, color):
        if len(self.pieces) < Stack.MAX:
            self.pieces.append((shape, color))
            put(board, shape, color, self.x, self.y)


s = Stack(2, 2)
for shape, color in [("washer", "red"), ("nut", "blue"), ("screw", "green"), ("washer", "red")]:
    s.add(shape, color)
put(board, "washer", "yellow", len(s.pieces), Stack.MAX)
