plan = {'washer': 'red'}
plan.update({'nut': 'blue'})
plan.setdefault('screw', 'green')
for i, (shape, color) in enumerate(plan.items()):
    put(board, shape, color, i, i)
