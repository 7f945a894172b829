x, y = 2, 6
x, y = y, x
put(board, 'nut', 'yellow', x, y)
