import bisect

ys = []
for y in [5, 1, 3, 7]:
    bisect.insort(ys, y)
for i, y in enumerate(ys):
    put(board, "washer", "yellow", i, y)
pos = bisect.bisect_left(ys, 4)
put(board, "nut", "red", 6, pos)
put(board, "nut", "red", 7, bisect.bisect_right(ys, 5))
