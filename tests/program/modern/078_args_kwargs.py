def place_many(shape, *cells, color="red", **extra):
    for x, y in cells:
        put(board, shape, extra.get("override", color), x, y)


place_many("washer", (0, 0), (1, 1), (2, 2), color="green")
place_many("nut", (0, 0), override="blue")
