cells = iter([(2, 0), (2, 1), (2, 2)])
while (cell := next(cells, None)) is not None:
    put(board, 'washer', 'yellow', *cell)
