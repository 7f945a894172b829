window = slice(1, 4)
cols = list(range(8))[window]
for y in cols:
    put(board, 'nut', 'red', 5, y)
