from enum import IntEnum


class Col(IntEnum):
    A = 0
    B = 1
    C = 2


colors = ["red", "green", "blue"]
for col in Col:
    put(board, "washer", colors[col], 3, col.value)
grid = [[None] * 3 for _ in range(3)]
grid[Col.B][Col.C] = "yellow"
put(board, "nut", grid[1][2], 3, int(Col.C))
put(board, "screw", "red", 5, Col.A)  # an IntEnum is not an exact int: type_error, as under plain exec
