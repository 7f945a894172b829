put(board, 'washer', 'red', 4, 4)
put(board, 'bridge-h', 'blue', 4, 4)
