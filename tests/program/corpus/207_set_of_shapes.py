shapes = {'washer', 'nut'}
for shape in shapes:
    put(board, shape, 'blue', 0, 0)
