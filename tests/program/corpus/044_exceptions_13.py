it = iter([3, 4])
next(it)
try:
    next(it)
    next(it)
except StopIteration:
    put(board, 'washer', 'yellow', 3, 4)
