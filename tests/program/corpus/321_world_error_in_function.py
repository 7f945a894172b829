def bs(board, colors, x, y):
    shapes = ['screw', 'bridge-v']
    for shape, color in zip(shapes, colors):
        put(board, shape, color, x, y)

bs(board, ('red', 'blue'), 2, 2)
