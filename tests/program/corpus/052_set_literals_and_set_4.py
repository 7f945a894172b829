rows = {r for r in range(4) if r % 2 == 0}
for r in sorted(rows):
    put(board, 'washer', 'yellow', r, 3)
