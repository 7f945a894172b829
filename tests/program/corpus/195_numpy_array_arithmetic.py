import numpy as np

offsets = np.array([[0, 0], [0, 1], [1, 0]])
origin = np.array([3, 3])
for x, y in offsets + origin:
    put(board, 'nut', 'blue', int(x), int(y))
