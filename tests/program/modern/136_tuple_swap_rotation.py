a, b = (0, 1), (6, 7)
a, b = b, a
put(board, "washer", "red", *a)
put(board, "washer", "blue", *b)
x, y = 3, 4
x, y = y, x
put(board, "nut", "green", x, y)
