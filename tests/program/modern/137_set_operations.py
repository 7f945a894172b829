row = {(0, y) for y in range(8)}
col = {(x, 0) for x in range(8)}
for x, y in sorted(row | col):
    put(board, "washer", "red" if (x, y) in row & col else "blue", x, y)
for x, y in sorted((row ^ col) - {(0, 7)})[:2]:
    put(board, "nut", "green", x, y)
