s = '{shape}|{color}|{x:d}'.format(shape='nut', color='blue', x=4)
shape, color, x = s.split('|')
put(board, shape, color, int(x), 4)
