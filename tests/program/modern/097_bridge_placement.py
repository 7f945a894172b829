def bridge(color, x, y, horizontal=True):
    put(board, "washer", color, x, y)
    if horizontal:
        put(board, "washer", color, x, y + 1)
        put(board, "bridge-h", color, x, y)
    else:
        put(board, "washer", color, x + 1, y)
        put(board, "bridge-v", color, x, y)


bridge("red", 0, 0)
bridge("blue", 3, 3, horizontal=False)
