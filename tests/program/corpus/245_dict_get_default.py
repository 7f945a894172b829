heights = {}
for x, y in [(1, 1), (1, 1), (2, 2)]:
    level = heights.get((x, y), 0)
    put(board, ['washer', 'nut'][level], 'blue', x, y)
    heights[(x, y)] = level + 1
