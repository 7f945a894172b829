for x in range(8):
    if 2 <= x < 5:
        put(board, 'washer', 'green', x, x)
