grid = {(x, y): 'red' if (x + y) % 2 else 'blue' for x in range(2) for y in range(2)}
for (x, y), c in grid.items():
    put(board, 'washer', c, x, y)
