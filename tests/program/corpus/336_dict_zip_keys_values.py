keys = ['washer', 'nut', 'screw']
values = ['blue', 'green', 'red']
plan = dict(zip(keys, values))
for shape in keys:
    put(board, shape, plan[shape], 1, 3)
