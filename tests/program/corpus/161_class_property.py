class Position:
    def __init__(self, row, col):
        self.row = row
        self.col = col

    @property
    def below(self):
        return Position(self.row + 1, self.col)

p = Position(1, 4)
put(board, 'nut', 'green', p.row, p.col)
put(board, 'nut', 'red', p.below.row, p.below.col)
