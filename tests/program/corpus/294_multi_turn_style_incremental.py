put(board, 'washer', 'red', 3, 3)
put(board, 'washer', 'red', 4, 3)
put(board, 'bridge-v', 'green', 3, 3)
put(board, 'screw', 'yellow', 3, 3)
