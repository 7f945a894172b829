try:
    raise KeyError('k')
except LookupError:
    put(board, 'screw', 'green', 5, 5)
