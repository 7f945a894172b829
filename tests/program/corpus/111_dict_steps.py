steps = [
    {'shape': 'nut', 'color': 'green', 'x': 7, 'y': 0},
    {'shape': 'washer', 'color': 'red', 'x': 7, 'y': 0},
    {'shape': 'screw', 'color': 'blue', 'x': 7, 'y': 0},
]
for s in steps:
    put(board, s['shape'], s['color'], s['x'], s['y'])
