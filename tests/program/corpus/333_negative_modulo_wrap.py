for i in range(-2, 2):
    put(board, 'washer', 'green', 0, i % 8)
