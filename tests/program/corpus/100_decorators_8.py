stack = [('washer', 'red'), ('nut', 'blue'), ('screw', 'yellow')]
for shape, color in stack:
    put(board, shape, color, 3, 4)
