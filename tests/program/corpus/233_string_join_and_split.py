spec = '|'.join(['screw', 'blue', '4', '4'])
shape, color, x, y = spec.split('|')
put(board, shape, color, int(x), int(y))
