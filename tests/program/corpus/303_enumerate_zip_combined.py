shapes = ['washer', 'nut', 'screw']
colors = ['yellow', 'green', 'red']
for i, (shape, color) in enumerate(zip(shapes, colors)):
    put(board, shape, color, i, 7 - i)
