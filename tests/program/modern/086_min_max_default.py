cells = [(3, 4), (1, 7), (6, 2)]
lo = min(cells, key=lambda c: c[1])
hi = max(cells, key=lambda c: c[0], default=None)
put(board, "washer", "red", *lo)
put(board, "washer", "blue", *hi)
empty = max([], default=(0, 0))
put(board, "nut", "green", *empty)
