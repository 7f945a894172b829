from abc import ABC, abstractmethod


class Builder(ABC):
    color = "red"

    def run(self):
        for x, y in self.positions():
            put(board, self.shape(), self.color, x, y)

    @abstractmethod
    def positions(self):
        ...

    @abstractmethod
    def shape(self):
        ...


class Corners(Builder):
    color = "blue"

    def positions(self):
        return [(0, 0), (0, 7), (7, 0), (7, 7)]

    def shape(self):
        return "washer"


class Incomplete(Builder):
    def positions(self):
        return []


Corners().run()
try:
    Incomplete()
except TypeError:
    put(board, "nut", "blue", 0, 0)
