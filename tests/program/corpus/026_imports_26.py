from math import *
put(board, 'washer', 'blue', floor(sqrt(9)), gcd(12, 8))
