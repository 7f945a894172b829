steps = ["washer red 0 7", "nut green 0 7", "washer blue 1 7"]
for step in steps:
    s, c, x, y = step.split(" ")
    put(board, s, c, int(x), int(y))
