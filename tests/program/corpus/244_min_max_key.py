cells = [(5, 2), (1, 7), (3, 3)]
x, y = min(cells, key=lambda c: c[0])
put(board, 'nut', 'red', x, y)
x, y = max(cells, key=lambda c: c[1] - c[0])
put(board, 'washer', 'red', x, y)
