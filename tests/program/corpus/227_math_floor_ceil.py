import math

cells = [(math.floor(2.7), math.ceil(2.2)), (math.trunc(5.9), int(math.fabs(-4)))]
for x, y in cells:
    put(board, 'screw', 'green', x, y)
