for y in {5, 1, 3}:
    put(board, 'screw', 'green', 4, y)
