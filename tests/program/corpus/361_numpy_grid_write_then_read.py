import numpy as np

grid = np.zeros((8, 8), dtype=int)
grid[1][2] = 1
grid[3, 4] = 2
for x in range(8):
    for y in range(8):
        if grid[x][y] == 1:
            put(board, 'washer', 'red', x, y)
        elif grid[x][y] == 2:
            put(board, 'nut', 'blue', x, y)
