code = f'{3:02d}'
w = 4
padded = f'{code:>{w}}'
put(board, 'washer', 'red', int(code), len(padded))
