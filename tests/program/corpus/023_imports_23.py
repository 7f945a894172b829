import copy
cells = [[0, 1], [2, 3]]
more = copy.deepcopy(cells)
more[0][0] = 4
more[1][1] = 5
for x, y in cells + more:
    put(board, 'washer', 'yellow', x, y)
