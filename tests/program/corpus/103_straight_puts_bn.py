board = init_board(8, 8)
put(board, 'bridge-v', 'green', 4, 3)
put(board, 'nut', 'red', 4, 3)
