from dataclasses import dataclass
from enum import Enum, auto


class Kind(Enum):
    PUT = auto()
    ROW = auto()


@dataclass
class Command:
    kind: Kind
    args: tuple


program = [Command(Kind.PUT, ("washer", "red", 0, 0)), Command(Kind.ROW, ("blue", 2))]
for cmd in program:
    match cmd:
        case Command(kind=Kind.PUT, args=(shape, color, x, y)):
            put(board, shape, color, x, y)
        case Command(Kind.ROW, (color, x)):
            for y in range(8):
                put(board, "washer", color, x, y)
