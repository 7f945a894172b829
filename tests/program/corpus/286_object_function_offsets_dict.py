def wnb(board, colors, x, y):
    parts = {
        'washer': (0, 0),
        'nut': (0, 1),
    }
    for (shape, (dx, dy)), color in zip(parts.items(), colors):
        put(board, shape, color, x + dx, y + dy)
    put(board, 'bridge-h', colors[2], x, y)

wnb(board, ['red', 'red', 'yellow'], 6, 3)
