from math import isqrt, prod

n = isqrt(prod([2, 2, 4]))
put(board, 'washer', 'yellow', n, n)
