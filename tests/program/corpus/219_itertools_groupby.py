from itertools import groupby

pieces = [('washer', 0), ('washer', 1), ('nut', 3)]
for shape, group in groupby(pieces, key=lambda p: p[0]):
    for _, y in group:
        put(board, shape, 'red', 4, y)
