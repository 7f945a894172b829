best = float('inf')
best_cell = None
for x, y in [(3, 3), (1, 2), (6, 0)]:
    d = abs(x - 0) + abs(y - 0)
    if d < best:
        best, best_cell = d, (x, y)
put(board, 'screw', 'green', *best_cell)
