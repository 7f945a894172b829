for i, c in enumerate({'red', 'green', 'blue', 'yellow'}):
    put(board, 'washer', c, 7, i)
