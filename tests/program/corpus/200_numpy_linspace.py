import numpy as np

for y in np.linspace(0, 6, 4):
    put(board, 'washer', 'yellow', 0, int(y))
