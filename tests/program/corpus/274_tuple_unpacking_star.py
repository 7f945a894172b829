first, *rest = [(0, 0), (0, 1), (0, 2)]
put(board, 'screw', 'red', *first)
for x, y in rest:
    put(board, 'washer', 'blue', x, y)
