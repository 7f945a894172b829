from __future__ import annotations
from typing import Optional


class Node:
    def __init__(self, x: int, y: int, parent: Optional[Node] = None) -> None:
        self.x, self.y, self.parent = x, y, parent

    def step(self, dx: int, dy: int) -> Node:
        return Node(self.x + dx, self.y + dy, self)


n = Node(0, 0)
for _ in range(5):
    n = n.step(1, 1)
while n is not None:
    put(board, "washer", "red", n.x, n.y)
    n = n.parent
