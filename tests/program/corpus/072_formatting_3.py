s = '%s %s %d' % ('washer', 'red', 3)
shape, color, x = s.split()
put(board, shape, color, int(x), 2)
