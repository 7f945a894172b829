rows = [["red"], ["green", "blue"], ["yellow", "red", "green"], []]
for x, row in enumerate(rows):
    match row:
        case []:
            put(board, "screw", "red", x, 7)
        case [c]:
            put(board, "washer", c, x, 0)
        case [c1, c2]:
            put(board, "washer", c1, x, 0)
            put(board, "washer", c2, x, 1)
        case [c1, *middle, c2]:
            put(board, "nut", c1, x, 0)
            put(board, "nut", c2, x, 1 + len(middle))
