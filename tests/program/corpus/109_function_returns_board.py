def build_tower(board, x, y):
    put(board, 'washer', 'red', x, y)
    put(board, 'nut', 'green', x, y)
    put(board, 'screw', 'yellow', x, y)
    return board
board = build_tower(init_board(8, 8), 3, 3)
