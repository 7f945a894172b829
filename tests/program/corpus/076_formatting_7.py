shape = 'washer'
msg = f'{shape!r} at {(1, 2)}'
put(board, shape, 'blue', len(msg) % 8, 2)
