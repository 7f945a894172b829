def _helper(b, x, y):
    put(b, 'nut', 'blue', x, y)
_helper(board, 3, 3)
