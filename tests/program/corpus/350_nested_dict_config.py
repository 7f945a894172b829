config = {
    'object': {'name': 'wn', 'x': 6, 'y': 6},
    'parts': [{'shape': 'washer', 'color': 'red'}, {'shape': 'nut', 'color': 'green'}],
}
obj = config['object']
for part in config['parts']:
    put(board, part['shape'], part['color'], obj['x'], obj['y'])
