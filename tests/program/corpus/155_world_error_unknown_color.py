put(board, 'nut', 'red', 0, 0)
put(board, 'nut', 'purple', 1, 0)
