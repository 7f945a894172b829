cells = [(2, 1), (0, 1), (1, 0)]
for x, y in sorted(cells, key=lambda c: (c[1], c[0])):
    put(board, 'washer', 'blue', x, y)
