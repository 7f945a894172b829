import operator
cells = sorted([(3, 1), (1, 2), (2, 0)], key=operator.itemgetter(1))
for x, y in cells:
    put(board, 'washer', 'red', x, y)
