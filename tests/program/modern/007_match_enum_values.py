from enum import Enum


class Shape(Enum):
    WASHER = "washer"
    NUT = "nut"
    SCREW = "screw"


def color_of(shape: Shape) -> str:
    match shape:
        case Shape.WASHER:
            return "red"
        case Shape.NUT:
            return "blue"
        case Shape.SCREW:
            return "yellow"


for i, s in enumerate(Shape):
    put(board, s.value, color_of(s), i, i)
