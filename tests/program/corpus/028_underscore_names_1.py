for _ in range(1):
    put(board, 'washer', 'red', 0, 0)
