from copy import copy

row = [(1, 0), (1, 1)]
more = copy(row)
more.append((1, 2))
for x, y in more:
    put(board, 'nut', 'yellow', x, y)
