cells = dict.fromkeys([(0, 0), (0, 1), (0, 0)], 'blue')
for (x, y), color in cells.items():
    put(board, 'washer', color, x, y)
