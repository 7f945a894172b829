shapes = ['washer', 'nut', 'screw']
colors = ['red', 'green', 'blue', 'yellow']
for x, color in enumerate(colors):
    for shape in shapes:
        put(board, shape, color, x, 0)
