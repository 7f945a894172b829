layout = {
    (0, 0): [('washer', 'red'), ('nut', 'blue')],
    (0, 1): [('screw', 'green')],
    (1, 0): [('nut', 'yellow'), ('washer', 'green'), ('screw', 'red')],
}
for (x, y), stack in layout.items():
    for shape, color in stack:
        put(board, shape, color, x, y)
