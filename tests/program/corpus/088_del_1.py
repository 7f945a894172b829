cells = [(0, 0), (1, 1), (2, 2)]
del cells[1]
d = {'x': 1}
del d['x']
for x, y in cells:
    put(board, 'washer', 'red', x, y)
