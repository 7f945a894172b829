values = ["washer", 3, 4.0, ("nut", "red"), None]
x = 0
for v in values:
    match v:
        case str(shape):
            put(board, shape, "red", x, 0)
        case int(n) | float(n):
            put(board, "washer", "blue", x, int(n))
        case (str() as shape, str() as color):
            put(board, shape, color, x, 1)
        case None:
            put(board, "screw", "green", x, 7)
    x += 1
