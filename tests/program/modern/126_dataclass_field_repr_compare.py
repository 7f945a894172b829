from dataclasses import dataclass, field


@dataclass(frozen=True)
class Brick:
    x: int
    y: int
    color: str = field(default="red", compare=False)
    note: str = field(default="", repr=False)


bricks = {Brick(1, 1, "blue"), Brick(1, 1, "green"), Brick(2, 2)}
for b in sorted(bricks, key=lambda b: (b.x, b.y)):
    put(board, "washer", "yellow", b.x, b.y)
print(repr(Brick(0, 0)))
