def place_and_report(board, colors, x, y):
    placed = []
    for i, color in enumerate(colors):
        put(board, 'washer', color, x, y + i)
        placed.append((x, y + i))
    return placed

cells = place_and_report(board, ['red', 'green', 'blue'], 4, 0)
put(board, 'nut', 'yellow', *cells[-1])
