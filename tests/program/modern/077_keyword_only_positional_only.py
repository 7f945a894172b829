def place(shape, /, color="red", *, x, y):
    put(board, shape, color, x, y)


place("washer", x=1, y=1)
place("nut", "blue", x=1, y=1)
opts = {"x": 5, "y": 5}
place("screw", **opts)
