def sn(board, colors, x, y):
    put(board, 'nut', colors[1], x, y + 1)
    put(board, 'screw', colors[0], x, y)

board = init_board(8, 8)
sn(board, ('red', 'blue'), 0, 0)
sn(board, ('green', 'yellow'), 7, 6)
