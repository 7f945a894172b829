x, y = divmod(19, 8)
put(board, 'nut', 'yellow', x, y)
put(board, 'screw', 'red', pow(2, 2), abs(-1))
