from itertools import accumulate
for y in accumulate([1, 1, 2]):
    put(board, 'washer', 'green', 5, y)
