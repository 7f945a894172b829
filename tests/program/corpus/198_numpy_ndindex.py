import numpy as np

for x, y in np.ndindex(2, 3):
    put(board, 'washer', 'blue', x + 5, y + 5)
