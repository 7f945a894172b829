for x, y in {(0, 1), (2, 3), (4, 5)}:
    put(board, 'washer', 'yellow', x, y)
