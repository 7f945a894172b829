_, y = (9, 4)
put(board, 'washer', 'yellow', 4, y)
