for y in (1, 4):
    put(board, 'bridge-v', 'yellow', 0, y)
    put(board, 'nut', 'green', 0, y)
    put(board, 'nut', 'green', 1, y)
