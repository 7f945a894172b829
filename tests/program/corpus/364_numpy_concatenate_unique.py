import numpy as np

cols = np.unique(np.concatenate([np.array([3, 1]), np.array([1, 5])]))
for y in cols:
    put(board, 'nut', 'red', 2, int(y))
