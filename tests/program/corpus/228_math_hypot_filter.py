import math

for x in range(8):
    for y in range(8):
        if math.hypot(x - 3, y - 3) <= 1:
            put(board, 'nut', 'blue', x, y)
