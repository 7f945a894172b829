for y in range(10):
    put(board, 'washer', 'green', 0, y)
