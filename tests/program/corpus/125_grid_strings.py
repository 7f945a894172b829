rows = [
    "w.w.",
    ".n.n",
]
for x, row in enumerate(rows):
    for y, ch in enumerate(row):
        if ch == 'w':
            put(board, 'washer', 'red', x, y)
        elif ch == 'n':
            put(board, 'nut', 'blue', x, y)
