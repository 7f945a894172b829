s = '%(shape)s' % {'shape': 'screw'}
put(board, s, 'yellow', 1, 1)
