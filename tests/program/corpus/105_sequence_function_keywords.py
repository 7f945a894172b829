def bn(board, colors, x, y):
    put(board, 'bridge-v', 'green', x=4, y=3)
    put(board, 'nut', 'red', x=4, y=3)
board = init_board(8, 8)
bn(board, ['green', 'red'], [4, 4], [3, 3])
