from abc import ABCMeta, abstractmethod


class Pattern(metaclass=ABCMeta):
    @abstractmethod
    def cells(self):
        raise NotImplementedError


class Checker(Pattern):
    def cells(self):
        return [(x, y) for x in range(4) for y in range(4) if (x + y) % 2 == 0]


for x, y in Checker().cells():
    put(board, "washer", "red", x, y)
