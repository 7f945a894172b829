plan = {'c': ('screw', 3), 'a': ('washer', 1), 'b': ('nut', 2)}
for key, (shape, y) in sorted(plan.items()):
    put(board, shape, 'yellow', 0, y)
