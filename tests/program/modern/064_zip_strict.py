xs = [0, 1, 2, 3]
ys = [7, 6, 5, 4]
colors = ["red", "green", "blue", "yellow"]
for x, y, c in zip(xs, ys, colors, strict=True):
    put(board, "washer", c, x, y)
try:
    list(zip([1, 2], [1], strict=True))
except ValueError:
    put(board, "nut", "red", 7, 7)
