points = [(0, 0), (0, 5), (5, 0), (3, 4), (7, 7, "extra")]

for p in points:
    match p:
        case (0, 0):
            put(board, "screw", "red", 0, 0)
        case (0, y):
            put(board, "washer", "blue", 0, y)
        case (x, 0):
            put(board, "washer", "green", x, 0)
        case (x, y):
            put(board, "nut", "yellow", x, y)
        case (x, y, *_):
            put(board, "washer", "yellow", x, y)
