for y in range(8):
    put(board, 'washer', 'blue', 4, y)
