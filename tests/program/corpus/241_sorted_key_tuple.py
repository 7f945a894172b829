pieces = [('nut', 'red', 2), ('washer', 'blue', 1), ('screw', 'green', 3)]
for shape, color, level in sorted(pieces, key=lambda p: p[2]):
    put(board, shape, color, 4, 2)
