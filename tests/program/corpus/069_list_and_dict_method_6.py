cols = list(range(5))
cols.extend([6, 7])
for y in cols[::3]:
    put(board, 'washer', 'green', 2, y)
