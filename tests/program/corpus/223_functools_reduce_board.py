from functools import reduce

steps = [('washer', 'red', 2, 2), ('nut', 'blue', 2, 2), ('screw', 'green', 2, 2)]
board = reduce(lambda b, s: put(b, *s), steps, board)
