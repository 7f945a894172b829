rows = [c.ljust(4, ".") for c in ["R", "GB", "YRG"]]
colors = {"R": "red", "G": "green", "B": "blue", "Y": "yellow"}
for x, row in enumerate(rows):
    for y, ch in enumerate(row.center(6, ".")):
        if ch in colors:
            put(board, "washer", colors[ch], x, y)
