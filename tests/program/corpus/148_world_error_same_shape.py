put(board, 'washer', 'red', 0, 0)
put(board, 'washer', 'blue', 0, 0)
