data = [{"x": 1, "y": 2}, {"x": 9, "y": 0}, {"pos": [3, 3]}]
for d in data:
    match d:
        case {"x": int(x), "y": int(y)} if (ok := 0 <= x < 8):
            put(board, "washer", "green", x, y)
        case {"pos": [x, y]}:
            put(board, "nut", "green", x, y)
        case _:
            put(board, "screw", "red", 7, 7)
