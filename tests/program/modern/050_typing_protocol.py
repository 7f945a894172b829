from typing import Protocol


class Placeable(Protocol):
    def place(self, b) -> None: ...


class Dot:
    def __init__(self, x, y):
        self.x, self.y = x, y

    def place(self, b) -> None:
        put(b, "washer", "yellow", self.x, self.y)


def place_all(items: list[Placeable]) -> None:
    for item in items:
        item.place(board)


place_all([Dot(1, 1), Dot(2, 2)])
