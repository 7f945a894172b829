import numpy as np

mask = np.array([[1, 0, 1], [0, 1, 0]])
xs, ys = np.where(mask == 1)
for x, y in zip(xs, ys):
    put(board, 'washer', 'red', int(x), int(y))
