put(board, 'bridge-h', 'red', 0, 0)
put(board, 'bridge-h', 'blue', 0, 0)
put(board, 'nut', 'yellow', 0, 1)
