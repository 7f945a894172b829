from itertools import zip_longest

shapes = ["washer", "nut", "screw"]
colors = ["red"]
for y, (s, c) in enumerate(zip_longest(shapes, colors, fillvalue="green")):
    put(board, s, c, 5, y)
