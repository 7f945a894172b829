from dataclasses import dataclass


@dataclass(slots=True, frozen=True)
class Cell:
    x: int
    y: int

    def neighbors(self):
        return [Cell(self.x + dx, self.y + dy) for dx, dy in ((0, 1), (1, 0)) if self.x + dx < 8 and self.y + dy < 8]


seen = {Cell(3, 3)}
for n in Cell(3, 3).neighbors():
    seen.add(n)
for c in sorted(seen, key=lambda c: (c.x, c.y)):
    put(board, "washer", "red", c.x, c.y)
