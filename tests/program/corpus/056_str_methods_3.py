s = 'bridge_h'
put(board, s.replace('_', '-'), 'yellow', 2, 5)
