left = {(0, 0), (1, 1)}
right = {(1, 1), (2, 2)}
for x, y in sorted(left | right):
    put(board, 'nut', 'yellow', x, y)
