import numpy as np

grid = np.zeros((8, 8), dtype=int)
grid[2, 3] = 1
grid[4, 5] = 1
rows, cols = grid.shape
for x in range(rows):
    for y in range(cols):
        if grid[x, y] == 1:
            put(board, 'screw', 'yellow', x, y)
