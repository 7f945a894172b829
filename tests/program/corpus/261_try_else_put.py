try:
    x = int('4')
except ValueError:
    x = 0
else:
    put(board, 'washer', 'green', x, x)
