def build():
    global board
    board = init_board(8, 8)
    put(board, 'screw', 'red', 7, 7)
build()
