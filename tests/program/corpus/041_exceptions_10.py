x = 3
assert 0 <= x < 8, 'x out of range'
put(board, 'washer', 'red', x, x)
