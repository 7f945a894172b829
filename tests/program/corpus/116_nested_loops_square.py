board = init_board(8, 8)
for x in range(2, 4):
    for y in range(5, 7):
        put(board, 'washer', 'yellow', x, y)
