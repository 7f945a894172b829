from collections import defaultdict
by_row = defaultdict(list)
for x, y in [(1, 1), (1, 2), (3, 3)]:
    by_row[x].append(y)
for x, ys in by_row.items():
    for y in ys:
        put(board, 'nut', 'red', x, y)
