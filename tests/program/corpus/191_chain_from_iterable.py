from itertools import chain

rows = [[(0, 0), (0, 1)], [(1, 0)], [(2, 5), (2, 6)]]
for x, y in chain.from_iterable(rows):
    put(board, 'washer', 'red', x, y)
