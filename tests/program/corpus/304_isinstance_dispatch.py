def place(item):
    if isinstance(item, tuple):
        put(board, 'washer', 'red', *item)
    elif isinstance(item, dict):
        put(board, item['shape'], item['color'], item['x'], item['y'])

for item in [(0, 0), {'shape': 'nut', 'color': 'green', 'x': 1, 'y': 1}]:
    place(item)
