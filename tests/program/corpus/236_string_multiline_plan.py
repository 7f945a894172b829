plan = """
washer red 0 0
nut blue 0 0
screw yellow 0 0
"""
for line in plan.strip().splitlines():
    shape, color, x, y = line.split()
    put(board, shape, color, int(x), int(y))
