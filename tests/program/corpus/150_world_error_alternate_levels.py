put(board, 'nut', 'red', 2, 2)
put(board, 'washer', 'green', 2, 2)
put(board, 'nut', 'blue', 2, 2)
