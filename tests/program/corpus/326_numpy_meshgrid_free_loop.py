import numpy as np

xs = np.arange(2)
ys = np.arange(3) + 4
for x in xs:
    for y in ys:
        put(board, 'washer', 'green', int(x), int(y))
