from operator import itemgetter

steps = [{'x': 3, 'y': 1, 'order': 2}, {'x': 3, 'y': 1, 'order': 1}]
shapes = {1: 'washer', 2: 'nut'}
for s in sorted(steps, key=itemgetter('order')):
    put(board, shapes[s['order']], 'green', s['x'], s['y'])
