def place(shape, color, row, column):
    put(board, shape, color, x=row - 1, y=column - 1)

place('washer', 'yellow', row=3, column=5)
place(shape='bridge-v', color='red', row=4, column=5)
