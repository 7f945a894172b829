colors = ['yellow'] * 4
for x, c in enumerate(colors):
    put(board, 'washer', c, x, 4)
