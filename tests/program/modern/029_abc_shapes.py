from abc import ABC, abstractmethod


class Placer(ABC):
    def __init__(self, color):
        self.color = color

    @abstractmethod
    def cells(self):
        ...

    def place(self, b):
        for x, y in self.cells():
            put(b, "washer", self.color, x, y)


class Row(Placer):
    def __init__(self, color, x):
        super().__init__(color)
        self.x = x

    def cells(self):
        return [(self.x, y) for y in range(8)]


class Diagonal(Placer):
    def cells(self):
        return [(i, i) for i in range(1, 8)]


for p in [Row("red", 0), Diagonal("blue")]:
    p.place(board)
