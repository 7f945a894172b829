import numpy as np

cells = np.array([[0, 1, 2], [5, 5, 5]]).T
for x, y in cells:
    put(board, 'washer', 'blue', int(x), int(y))
