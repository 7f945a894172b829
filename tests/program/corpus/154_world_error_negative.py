put(board, 'washer', 'red', 0, 0)
put(board, 'washer', 'red', -1, 0)
