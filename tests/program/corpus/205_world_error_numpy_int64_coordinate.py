import numpy as np
put(board, "nut", "blue", 0, 0)

for y in np.arange(3):
    put(board, 'washer', 'red', 2, y)
