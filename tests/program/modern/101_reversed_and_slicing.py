stack = ["washer", "nut", "screw"]
for shape in stack[::-1][-1:] + stack[1:]:
    pass
for i, shape in enumerate(reversed(stack)):
    put(board, shape, "red", i, 0)
for y in range(8)[::3]:
    put(board, "washer", "green", 7, y)
