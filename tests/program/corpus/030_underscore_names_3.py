_cells = [(1, 2), (2, 1)]
for _x, _y in _cells:
    put(board, 'screw', 'green', _x, _y)
