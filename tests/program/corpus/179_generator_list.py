def ring(x, y):
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            if dx or dy:
                yield x + dx, y + dy

cells = list(ring(4, 4))
for x, y in cells:
    put(board, 'washer', 'green', x, y)
