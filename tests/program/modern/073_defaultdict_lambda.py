from collections import defaultdict

by_row = defaultdict(list)
for x, y, c in [(0, 1, "red"), (0, 2, "blue"), (3, 3, "green")]:
    by_row[x].append((y, c))
level = defaultdict(lambda: "washer")
level[3] = "nut"
for x, items in sorted(by_row.items()):
    for y, c in items:
        put(board, level[x], c, x, y)
