from bisect import bisect

breakpoints = [2, 4, 6]
colors = ["red", "green", "blue", "yellow"]
for y in range(8):
    put(board, "washer", colors[bisect(breakpoints, y)], 4, y)
