for x in (5, 6):
    put(board, 'nut', 'blue', x, 1)
put(board, 'bridge-v', 'green', 5, 1)
put(board, 'washer', 'red', 5, 1)
