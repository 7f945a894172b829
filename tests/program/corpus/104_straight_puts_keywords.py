board = init_board(8, 8)
put(board, 'washer', 'blue', x=2, y=5)
put(board, 'nut', 'yellow', x=2, y=5)
put(board, 'screw', 'red', x=2, y=5)
