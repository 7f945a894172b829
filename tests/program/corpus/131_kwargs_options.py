def build(board, **opts):
    x = opts.get('x', 0)
    y = opts.get('y', 0)
    color = opts.get('color', 'red')
    put(board, 'nut', color, x, y)

build(board, x=4, y=4, color='blue')
build(board, x=5)
