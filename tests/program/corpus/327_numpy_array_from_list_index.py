import numpy as np

coords = np.array([(0, 6), (1, 6), (2, 6)])
for i in range(len(coords)):
    put(board, 'washer', 'red', int(coords[i][0]), int(coords[i][1]))
