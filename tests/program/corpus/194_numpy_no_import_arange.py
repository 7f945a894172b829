for y in np.arange(0, 8, 2):
    put(board, 'washer', 'red', 1, int(y))
