n = 5
put(board, 'washer', 'red', int(f'{n:b}', 2), int('{:o}'.format(6), 8))
