list(map(lambda y: put(board, 'washer', 'red', 7, y), range(0, 8, 3)))
