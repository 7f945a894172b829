coords = list(map(int, ['1', '2', '3']))
for c in coords:
    put(board, 'washer', 'yellow', c, c)
