cells = [(2, 1), (0, 5), (7, 3)]
cells.sort(key=lambda c: c[1], reverse=True)
for i, (x, y) in enumerate(cells):
    put(board, ["washer", "nut", "screw"][i], "blue", x, y)
