from enum import Enum, auto


class Shape(Enum):
    WASHER = auto()
    NUT = auto()
    SCREW = auto()


NAMES = {Shape.WASHER: "washer", Shape.NUT: "nut", Shape.SCREW: "screw"}
used = set()
for y, s in enumerate([Shape.WASHER, Shape.NUT, Shape.WASHER, Shape.SCREW]):
    put(board, NAMES[s], "yellow", 5, y)
    used.add(s)
put(board, "washer", "red", 7, len(used))
print(Shape.NUT, repr(Shape.NUT))
