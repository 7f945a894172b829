from enum import Flag, auto


class Side(Flag):
    TOP = auto()
    LEFT = auto()
    RIGHT = auto()
    BOTTOM = auto()


wanted = Side.TOP | Side.LEFT
for x in range(8):
    for y in range(8):
        if (Side.TOP in wanted and x == 0) or (Side.LEFT in wanted and y == 0):
            put(board, "washer", "yellow", x, y)
