import textwrap

layout = textwrap.dedent("""
    R..B
    .GG.
    Y..R
""").strip().splitlines()
colors = {"R": "red", "G": "green", "B": "blue", "Y": "yellow"}
for x, row in enumerate(layout):
    for y, ch in enumerate(row):
        if ch != ".":
            put(board, "washer", colors[ch], x, y)
