order = 'red green blue'.split()[::-1]
for i, c in enumerate(order):
    put(board, 'nut', c, 6, i)
