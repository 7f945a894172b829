layout = [
    [None, 'washer', None],
    ['nut', 'screw', 'nut'],
]
for x, row in enumerate(layout):
    for y, shape in enumerate(row):
        if shape is not None:
            put(board, shape, 'green', x + 2, y + 2)
