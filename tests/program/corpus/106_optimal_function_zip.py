def bbbns(board, colors, x, y):
    shapes = ['bridge-h', 'bridge-h', 'bridge-v', 'nut', 'screw']
    for shape, color, dx, dy in zip(shapes, colors, [0, 1, 0, 0, 0], [0, 1, 1, 1, 1]):
            put(board, shape, color, x + dx, y + dy)
board = init_board(8, 8)
bbbns(board, ('yellow', 'green', 'blue', 'red', 'blue'), 1, 1)
