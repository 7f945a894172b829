groups = [[(0, 0), (0, 1)], [(2, 0)]]
for x, y in sum(groups, []):
    put(board, 'washer', 'green', x, y)
