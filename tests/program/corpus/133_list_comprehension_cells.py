cells = [(x, 2 * x) for x in range(4)]
for x, y in cells:
    put(board, 'washer', 'blue', x, y)
