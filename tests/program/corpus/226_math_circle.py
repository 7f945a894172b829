import math

for k in range(8):
    angle = 2 * math.pi * k / 8
    x = round(3.5 + 3 * math.cos(angle))
    y = round(3.5 + 3 * math.sin(angle))
    put(board, 'washer', 'red', x, y)
