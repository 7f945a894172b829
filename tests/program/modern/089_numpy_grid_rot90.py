import numpy as np

pattern = np.array([[1, 0], [0, 2]])
big = np.zeros((8, 8), dtype=int)
big[:2, :2] = pattern
colors = {1: "red", 2: "blue"}
for (x, y), v in np.ndenumerate(big):
    if v:
        put(board, "washer", colors[int(v)], x, y)
