xs = [1, 2, 3]
ys = [4, 5, 6]
for x, y in zip(xs, ys):
    put(board, 'screw', 'yellow', x, y)
