from enum import Enum, unique


@unique
class Level(Enum):
    LOW = 1
    MID = 2
    HIGH = 3


for level in sorted(Level, key=lambda l: l.value, reverse=True):
    for z in range(level.value):
        put(board, "washer" if z == 0 else "nut", "red", level.value, 2)  if z == 0 else None
    put(board, "screw", "blue", level.value, 4)
