import math

put(board, 'washer', 'red', math.comb(4, 2), math.perm(3, 1))
