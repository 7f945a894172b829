put(board, 'screw', 'red', 3, 3)
put(board, 'nut', 'blue', 3, 3)
