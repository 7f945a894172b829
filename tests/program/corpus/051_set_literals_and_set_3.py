a = {1, 2, 3}
b = {2, 3, 4}
for y in sorted(a & b | {7}):
    put(board, 'screw', 'red', 0, y)
for y in sorted(a.union(b) - a.intersection(b)):
    put(board, 'washer', 'green', 1, y)
