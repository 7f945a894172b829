def nwb(board, colors, x, y):
    shapes = ['nut', 'washer', 'bridge-h']
    for shape, color, dx, dy in zip(shapes, colors, [0, 0, 0], [0, 1, 0]):
        put(board, shape, color, x + dx, y + dy)
nwb(board, ('blue', 'green', 'red'), 2, 0)
