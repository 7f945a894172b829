from itertools import product

for x, y in product(range(3, 5), range(3, 5)):
    put(board, 'washer', 'red', x, y)
