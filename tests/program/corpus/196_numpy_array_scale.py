import numpy as np

ys = np.array([0, 1, 2]) * 2
for y in ys:
    put(board, 'washer', 'green', 5, int(y))
