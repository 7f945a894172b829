board = init_board(8, 8)

def place(shape, color, x, y):
    put(board, shape, color, x, y)

place('washer', 'yellow', 1, 1)
place('bridge-h', 'blue', 2, 2)
