[put(board, 'nut', 'green', 7, y) for y in range(4)]
