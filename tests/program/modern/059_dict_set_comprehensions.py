colors = ["red", "green", "blue", "yellow"]
index = {c: i for i, c in enumerate(colors)}
lengths = {len(c) for c in colors}
for c, i in index.items():
    put(board, "washer", c, i, i)
for y in sorted(lengths):
    put(board, "nut", "red", 6, y)
inverse = {v: k for k, v in index.items() if v % 2}
put(board, "screw", inverse[3], 7, 7)
