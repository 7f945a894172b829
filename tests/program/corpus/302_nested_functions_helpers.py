def build(board):
    def base(x, y):
        put(board, 'washer', 'blue', x, y)

    def top(x, y):
        put(board, 'screw', 'red', x, y)

    for y in range(2):
        base(6, y)
        top(6, y)
    return board

board = build(board)
