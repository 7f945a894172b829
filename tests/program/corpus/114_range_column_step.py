for x in range(0, 8, 2):
    put(board, 'nut', 'red', x, 7)
