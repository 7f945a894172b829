from abc import ABC, abstractmethod


class Base(ABC):
    @abstractmethod
    def build(self, b):
        pass


class Tower(Base):
    def build(self, b):
        put(b, "washer", "red", 2, 2)
        put(b, "nut", "blue", 2, 2)


try:
    Base()
except TypeError as e:
    put(board, "screw", "green", 7, 7)
Tower().build(board)
