from collections import namedtuple

Cell = namedtuple("Cell", ["x", "y", "color"])

cells = [Cell(0, 1, "red"), Cell(3, 3, "green"), Cell(7, 0, "blue")]
for cell in cells:
    match cell:
        case Cell(x, y, "red"):
            put(board, "washer", "red", x, y)
        case Cell(x=x, y=y, color=c):
            put(board, "nut", c, x, y)
