for x in reversed(range(3)):
    put(board, 'screw', 'green', x, x + 1)
