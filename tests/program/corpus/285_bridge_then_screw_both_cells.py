put(board, 'bridge-v', 'yellow', 2, 7)
put(board, 'screw', 'red', 2, 7)
put(board, 'screw', 'blue', 3, 7)
