cells = [(0, 0), (1, 1), (2, 2), (3, 3)]
for (x1, y1), (x2, y2) in zip(cells, cells[1:]):
    put(board, 'washer', 'yellow', x1, y2)
