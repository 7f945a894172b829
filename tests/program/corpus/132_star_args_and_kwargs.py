def stack(board, x, y, *shapes, color='yellow', **extra):
    for shape in shapes:
        put(board, shape, extra.get(shape, color), x, y)

stack(board, 6, 6, 'washer', 'nut', 'screw', screw='red')
