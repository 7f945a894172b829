from enum import IntEnum, auto


class Row(IntEnum):
    TOP = auto()
    MIDDLE = auto()
    BOTTOM = auto()


for r in Row:
    put(board, "washer", "blue", int(r), r * 2)
put(board, "nut", "red", Row.BOTTOM + 1, Row.TOP + 0)
put(board, "screw", "green", int(max(Row)), len(Row.MIDDLE.name))
