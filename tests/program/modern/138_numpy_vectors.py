import numpy as np

start = np.array([1, 1])
direction = np.array([1, 2])
for k in range(3):
    x, y = start + k * direction
    put(board, "washer", "red", int(x), int(y))
print(np.linalg.norm(direction))
