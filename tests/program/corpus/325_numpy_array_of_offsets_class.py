import numpy as np

class Shape:
    def __init__(self, offsets):
        self.offsets = np.array(offsets)

    def cells(self, x, y):
        return self.offsets + np.array([x, y])

for cx, cy in Shape([[0, 0], [1, 0], [1, 1]]).cells(2, 4):
    put(board, 'nut', 'yellow', int(cx), int(cy))
