for i, shape in enumerate(['washer', 'nut', 'screw'], start=2):
    put(board, shape, 'red', i, i)
