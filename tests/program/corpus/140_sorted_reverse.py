for x in sorted([5, 1, 3], reverse=True):
    put(board, 'washer', 'green', x, 0)
