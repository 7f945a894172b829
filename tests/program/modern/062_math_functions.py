import math

center = (3.5, 3.5)
for x in range(8):
    for y in range(8):
        d = math.dist(center, (x, y))
        if math.isclose(d, 2.5, abs_tol=0.4):
            put(board, "washer", "yellow", x, y)
put(board, "nut", "red", math.prod([1, 2, 3]), math.comb(4, 2) - 5)
put(board, "screw", "blue", math.isqrt(50), math.floor(math.hypot(3, 4)))
