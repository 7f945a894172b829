board = init_board(8, 8)
place = lambda x, y, c='red': put(board, 'washer', c, x, y)
place(4, 4)
place(4, 5, c='green')
