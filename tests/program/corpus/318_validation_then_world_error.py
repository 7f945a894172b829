def build(board, steps):
    for shape, color, x, y in steps:
        if shape not in ('washer', 'nut', 'screw', 'bridge-h', 'bridge-v'):
            raise ValueError(shape)
        put(board, shape, color, x, y)

build(board, [('screw', 'red', 4, 4), ('washer', 'blue', 4, 4)])
