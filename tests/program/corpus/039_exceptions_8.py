items = [1, 2]
try:
    items[5]
except IndexError:
    pass
put(board, 'washer', 'red', len(items), 0)
