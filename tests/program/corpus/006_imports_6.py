from itertools import chain, islice
for y in islice(chain([1, 2], [5, 6]), 3):
    put(board, 'washer', 'blue', 0, y)
