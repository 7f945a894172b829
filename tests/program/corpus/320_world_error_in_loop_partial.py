for level, shape in enumerate(['washer', 'nut', 'nut']):
    put(board, shape, 'blue', 1, 4)
