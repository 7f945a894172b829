import numpy as np

colors = np.array([['red', 'green'], ['blue', 'yellow']])
for x in range(2):
    for y in range(2):
        put(board, 'nut', str(colors[x, y]), x, y)
