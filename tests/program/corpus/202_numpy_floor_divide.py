import numpy as np

idx = np.arange(8)
for x, y in zip(idx // 2, idx % 2):
    put(board, 'nut', 'green', int(x), int(y))
