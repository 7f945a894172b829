cells = [(1, 2), (3, 4), (5, 6)]
xs, ys = zip(*cells)
for x, y in zip(xs, reversed(ys)):
    put(board, 'nut', 'red', x, y)
