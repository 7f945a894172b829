put(board, 'washer', 'red', 1, 1)
put(board, 'nut', 'red', 4 / 2, 1)
