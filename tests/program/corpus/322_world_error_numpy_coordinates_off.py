import numpy as np

for y in np.arange(6, 10).tolist():
    put(board, 'washer', 'red', 0, y)
