shapes = ['washer', 'nut', 'screw']
colors = ['green', 'yellow', 'blue']
for i in range(len(shapes)):
    put(board, shapes[i], colors[i], 2, 2)
