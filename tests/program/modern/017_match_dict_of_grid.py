layout = ["R.G", ".B.", "Y.R"]
colors = {"R": "red", "G": "green", "B": "blue", "Y": "yellow"}
for x, row in enumerate(layout):
    for y, ch in enumerate(row):
        match ch:
            case ".":
                continue
            case letter if letter in colors:
                put(board, "washer", colors[letter], x, y)
