import numpy as np

grid = np.zeros((8, 8), dtype=int)
grid[::2, ::3] = 1
xs, ys = np.nonzero(grid)
for x, y in zip(xs.tolist(), ys.tolist()):
    put(board, "washer", "yellow", x, y)
