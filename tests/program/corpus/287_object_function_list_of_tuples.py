def build_object(board, colors, x, y):
    layout = [('bridge-v', 0, 0), ('washer', 0, 1), ('washer', 1, 1), ('bridge-v', 0, 1)]
    for (shape, dx, dy), color in zip(layout, colors):
        put(board, shape, color, x + dx, y + dy)

build_object(board, ('blue', 'green', 'green', 'red'), 1, 1)
