def bridge(b, x, y, color='yellow', *, vertical=False):
    put(b, 'bridge-v' if vertical else 'bridge-h', color, x, y)
put(board, 'washer', 'red', 0, 0)
put(board, 'washer', 'red', 0, 1)
bridge(board, 0, 0)
bridge(board, 3, 3, vertical=True)
