from dataclasses import dataclass


@dataclass
class Part:
    x: int
    y: int


@dataclass
class Colored(Part):
    color: str = "red"

    def place(self):
        put(board, "washer", self.color, self.x, self.y)


for c in [Colored(0, 0), Colored(1, 1, "blue")]:
    c.place()
