def f():
    raise RuntimeError('stop')
try:
    f()
except RuntimeError as err:
    put(board, 'nut', 'yellow', 6, len(str(err)))
