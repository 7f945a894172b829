for i in range(8):
    put(board, 'washer', 'green', i, i)
    if i != 7 - i:
        put(board, 'washer', 'yellow', i, 7 - i)
