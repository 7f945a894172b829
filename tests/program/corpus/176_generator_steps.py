def steps(colors):
    shapes = ['washer', 'nut', 'screw']
    for shape, color in zip(shapes, colors):
        yield shape, color

for shape, color in steps(['green', 'blue', 'yellow']):
    put(board, shape, color, 3, 6)
