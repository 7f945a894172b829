from collections import Counter

cells = [(2, 2), (2, 2), (5, 5)]
seen = Counter()
for x, y in cells:
    shape = ['washer', 'nut', 'screw'][seen[(x, y)]]
    put(board, shape, 'green', x, y)
    seen[(x, y)] += 1
