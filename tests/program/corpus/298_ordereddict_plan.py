from collections import OrderedDict

plan = OrderedDict()
plan['washer'] = 'green'
plan['nut'] = 'blue'
plan['screw'] = 'red'
for shape, color in plan.items():
    put(board, shape, color, 7, 7)
