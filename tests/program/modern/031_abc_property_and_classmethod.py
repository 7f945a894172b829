import abc


class Structure(abc.ABC):
    @property
    @abc.abstractmethod
    def color(self) -> str:
        raise NotImplementedError

    @classmethod
    def make(cls):
        return cls()


class RedWall(Structure):
    @property
    def color(self):
        return "red"


w = RedWall.make()
for y in range(4):
    put(board, "washer", w.color, 5, y)
print(isinstance(w, Structure), issubclass(RedWall, abc.ABC))
