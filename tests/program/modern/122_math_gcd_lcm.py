import math

step = math.gcd(12, 8)
for y in range(0, 8, step):
    put(board, "washer", "red", 0, y)
put(board, "nut", "blue", math.lcm(2, 3), 1)
put(board, "screw", "green", math.ceil(6.2), math.trunc(-1.5) + 2)
