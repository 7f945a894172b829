cells = [(3, 1), (1, 2), (2, 0)]
cells.sort()
cells.reverse()
for x, y in cells:
    put(board, 'washer', 'red', x, y)
