import numpy as np

plan = np.zeros((8, 8), dtype=int)
plan[6, 1:4] = 1
for x, y in np.argwhere(plan == 1):
    put(board, 'screw', 'green', int(x), int(y))
