import bisect

placed = [(0, "red"), (3, "blue"), (6, "green")]
for y, color in [(4, "yellow"), (1, "red")]:
    bisect.insort(placed, (y, color), key=lambda p: p[0])
for x, (y, color) in enumerate(placed):
    put(board, "washer", color, x, y)
i = bisect.bisect_left(placed, 3, key=lambda p: p[0])
put(board, "nut", placed[i][1], i, placed[i][0])
