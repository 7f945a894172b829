actions = {
    "row": lambda x: [(x, y) for y in range(8)],
    "col": lambda y: [(x, y) for x in range(8)],
}
for kind, n, color in [("row", 0, "red"), ("col", 7, "blue")]:
    for x, y in actions[kind](n):
        if (x, y) != (0, 7):
            put(board, "washer", color, x, y)
