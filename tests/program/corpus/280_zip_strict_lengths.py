shapes = ['washer', 'nut']
colors = ['blue', 'red']
for s, c in zip(shapes, colors, strict=True):
    put(board, s, c, 6, 0)
