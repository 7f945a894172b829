from copy import deepcopy

def can_place(board, shape, color, x, y):
    trial = deepcopy(board)
    try:
        put(trial, shape, color, x, y)
        return True
    except Exception:
        return False

put(board, 'screw', 'yellow', 4, 4)
for shape, x, y in [('nut', 4, 4), ('nut', 4, 5), ('washer', 4, 4)]:
    if can_place(board, shape, 'green', x, y):
        put(board, shape, 'green', x, y)
