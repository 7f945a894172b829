color = ' '.join(['red'])
put(board, 'washer', color, 1, 1)
