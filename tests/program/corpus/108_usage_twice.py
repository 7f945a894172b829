def bs(board, colors, x, y):
    shapes = ['bridge-v', 'screw']
    for shape, color, dx, dy in zip(shapes, colors, [0, 0], [0, 0]):
        put(board, shape, color, x + dx, y + dy)
bs(board, ('red', 'blue'), 2, 2)
bs(board, ('yellow', 'green'), 5, 6)
