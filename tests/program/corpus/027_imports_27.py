import math as m, itertools as it
for x, y in it.product(range(m.isqrt(4)), repeat=2):
    put(board, 'nut', 'yellow', x, y)
