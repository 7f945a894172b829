heights = {}
for x, y in [(1, 1), (1, 1), (2, 2), (1, 1)]:
    h = heights.setdefault((x, y), 0)
    put(board, ["washer", "nut", "screw"][h], "red", x, y)
    heights[(x, y)] = heights.get((x, y), 0) + 1
