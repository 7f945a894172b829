import numpy as np

heights = np.array([1, 2, 3])
x = int(heights.sum())
y = int(np.max(heights))
put(board, 'screw', 'blue', x, y)
