import numpy as np

cells = (np.array([[1, 1], [2, 2]]) + 1).tolist()
for x, y in cells:
    put(board, 'washer', 'blue', x, y)
