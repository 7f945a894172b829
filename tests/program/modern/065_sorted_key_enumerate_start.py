pieces = [("screw", 3), ("washer", 1), ("nut", 2)]
for x, (shape, rank) in enumerate(sorted(pieces, key=lambda p: p[1]), start=1):
    put(board, shape, "blue", x, rank)
best = max(pieces, key=lambda p: (p[1], p[0]))
put(board, best[0], "red", 0, 0)
