ys = list(filter(lambda y: y % 2 == 0, range(8)))
for y in ys:
    put(board, 'nut', 'red', 0, y)
