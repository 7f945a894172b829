def colors():
    yield from ["red", "green", "blue"]


g = colors()
y = 0
while (c := next(g, None)) is not None:
    put(board, "washer", c, 4, y)
    y += 1
