put(board, 'screw', 'red', 6, 2)
put(board, 'screw', 'red', 6, 3)
put(board, 'bridge-h', 'green', 6, 2)
