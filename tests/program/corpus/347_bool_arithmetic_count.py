flags = [True, False, True, True]
put(board, 'washer', 'red', sum(flags), flags.count(False))
