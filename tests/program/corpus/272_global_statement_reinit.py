def reset():
    global board
    board = init_board(8, 8)

put(board, 'nut', 'red', 0, 0)
reset()
put(board, 'washer', 'blue', 1, 1)
