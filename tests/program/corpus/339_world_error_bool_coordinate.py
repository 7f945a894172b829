put(board, 'washer', 'red', 0, 0)
put(board, 'nut', 'red', True, 0)
