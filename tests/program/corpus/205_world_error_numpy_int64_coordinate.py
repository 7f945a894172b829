import numpy as np

for y in np.arange(3):
    put(board, 'washer', 'red', 2, y)
