import numpy as np

levels = np.array([0, 1, 2, 3, 4, 5])
levels[levels > 3] = 0
for y, v in enumerate(levels):
    if v:
        put(board, 'washer', 'green', int(v), y)
