def build(board, *pieces, **opts):
    for shape, color in pieces:
        put(board, shape, color, opts['x'], opts['y'])
build(board, ('washer', 'red'), ('nut', 'blue'), x=5, y=2)
