import numpy as np

xs, ys = np.meshgrid(np.arange(2), np.arange(3), indexing='ij')
for x, y in zip(xs.flatten(), ys.flatten()):
    put(board, 'washer', 'yellow', int(x) + 4, int(y) + 4)
