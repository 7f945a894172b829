from math import pi, cos, sin
x = round(3 + 3 * cos(pi))
y = round(3 + 3 * sin(pi / 2))
put(board, 'screw', 'green', x, y)
