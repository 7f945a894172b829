key = 'r3'
put(board, 'washer', 'green', int(key[1:].zfill(2)), len(key.center(5)) - 4)
