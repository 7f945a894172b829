grid = [[(x + y) % 3 == 0 for y in range(8)] for x in range(8)]
for x, row in enumerate(grid):
    if any(row) and not all(row):
        for y, on in enumerate(row):
            if on:
                put(board, "washer", "blue", x, y)
