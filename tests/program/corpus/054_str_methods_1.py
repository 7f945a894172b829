spec = 'washer:red:7:3'
shape, color, x, y = spec.split(':')
put(board, shape, color, int(x), int(y))
