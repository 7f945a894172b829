cells = [(1, 1), (2, 2)]
if all(0 <= x < 8 and 0 <= y < 8 for x, y in cells) and not any(x == y == 0 for x, y in cells):
    for x, y in cells:
        put(board, 'nut', 'blue', x, y)
