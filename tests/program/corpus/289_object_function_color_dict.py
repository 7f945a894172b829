def tower(board, colors, x, y):
    order = ['washer', 'nut', 'screw']
    for shape in order:
        put(board, shape, colors[shape], x, y)

tower(board, {'washer': 'blue', 'nut': 'red', 'screw': 'yellow'}, 2, 5)
