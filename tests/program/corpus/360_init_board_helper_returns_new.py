def fresh():
    b = init_board(8, 8)
    put(b, 'washer', 'blue', 0, 0)
    return b

old = board
board = fresh()
put(board, 'nut', 'red', 0, 0)
