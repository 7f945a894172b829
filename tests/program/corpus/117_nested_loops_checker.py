for x in range(8):
    for y in range(8):
        if (x + y) % 2 == 0:
            put(board, 'nut', 'blue', x, y)
