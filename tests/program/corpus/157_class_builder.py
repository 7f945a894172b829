class Builder:
    def __init__(self, board):
        self.board = board

    def place(self, shape, color, x, y):
        put(self.board, shape, color, x, y)
        return self

builder = Builder(board)
builder.place('washer', 'red', 2, 2).place('nut', 'blue', 2, 2)
