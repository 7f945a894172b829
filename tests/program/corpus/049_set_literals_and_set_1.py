cells = {(0, 0), (1, 1), (0, 0)}
for x, y in sorted(cells):
    put(board, 'washer', 'red', x, y)
