layout = [
    [[('washer', 'red'), ('nut', 'blue')], []],
    [[], [('screw', 'yellow')]],
]
for x, row in enumerate(layout):
    for y, stack in enumerate(row):
        for shape, color in stack:
            put(board, shape, color, x, y)
