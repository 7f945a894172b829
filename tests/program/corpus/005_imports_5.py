import itertools
for x, y in itertools.combinations(range(4), 2):
    put(board, 'nut', 'red', x, y)
