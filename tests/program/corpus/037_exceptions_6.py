try:
    x = 1 / 0
except ZeroDivisionError:
    x = 0
else:
    x = 5
put(board, 'washer', 'green', x, x)
