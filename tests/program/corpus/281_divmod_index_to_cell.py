for i in [0, 9, 18, 27]:
    x, y = divmod(i, 8)
    put(board, 'screw', 'green', x, y)
