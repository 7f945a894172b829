shapes = ['washer', 'nut', 'screw']
colors = ['red', 'blue', 'green', 'yellow']
for shape, color in zip(shapes, colors):
    put(board, shape, color, 6, 2)
