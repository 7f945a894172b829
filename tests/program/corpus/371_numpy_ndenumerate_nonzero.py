import numpy as np

layout = np.zeros((8, 8), dtype=int)
layout[2, 2:5] = 1
layout[6, 1] = 2
for (x, y), kind in np.ndenumerate(layout):
    if kind == 1:
        put(board, 'washer', 'yellow', x, y)
rows, cols = np.nonzero(layout == 2)
for x, y in zip(rows, cols):
    put(board, 'screw', 'green', int(x), int(y))
