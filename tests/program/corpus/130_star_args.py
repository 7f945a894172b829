def place_all(board, *cells):
    for x, y in cells:
        put(board, 'washer', 'green', x, y)

place_all(board, (1, 1), (2, 2), (3, 3))
