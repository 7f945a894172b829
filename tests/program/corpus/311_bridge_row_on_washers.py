for y in range(0, 6, 2):
    put(board, 'washer', 'red', 2, y)
    put(board, 'washer', 'red', 2, y + 1)
    put(board, 'bridge-h', 'blue', 2, y)
