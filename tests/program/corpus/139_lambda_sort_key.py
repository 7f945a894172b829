cells = [(3, 1), (0, 4), (2, 2)]
for x, y in sorted(cells, key=lambda c: c[1]):
    put(board, 'nut', 'red', x, y)
