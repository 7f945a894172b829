from dataclasses import dataclass, field


@dataclass(order=True)
class Spot:
    sort_key: int = field(init=False, repr=False)
    x: int
    y: int

    def __post_init__(self):
        self.sort_key = self.x * 8 + self.y


spots = sorted([Spot(3, 1), Spot(0, 5), Spot(2, 2)])
for i, s in enumerate(spots):
    put(board, "washer", ["red", "green", "blue"][i], s.x, s.y)
