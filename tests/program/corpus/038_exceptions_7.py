try:
    v = int('abc')
except (ValueError, TypeError):
    v = 6
put(board, 'screw', 'yellow', v, 1)
