from itertools import product
for x, y in product(range(2), range(3)):
    put(board, 'washer', 'yellow', x, y)
