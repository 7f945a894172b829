from itertools import pairwise

path = [(0, 0), (0, 3), (4, 3), (4, 7)]
for (x1, y1), (x2, y2) in pairwise(path):
    if x1 == x2:
        for y in range(min(y1, y2), max(y1, y2)):
            put(board, "washer", "red", x1, y)
    else:
        for x in range(min(x1, x2), max(x1, x2)):
            put(board, "washer", "red", x, y1)
put(board, "nut", "red", *path[-1])
