cells = list((x, x + 1) for x in range(0, 6, 2))
for x, y in cells:
    put(board, 'washer', 'blue', x, y)
