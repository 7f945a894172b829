class Piece:
    count = 0

    def __init__(self, shape, color):
        self.shape = shape
        self.color = color
        Piece.count += 1

    @classmethod
    def red(cls, shape):
        return cls(shape, 'red')

    def put_on(self, board, x, y):
        put(board, self.shape, self.color, x, y)

for i, p in enumerate([Piece.red('washer'), Piece('nut', 'yellow')]):
    p.put_on(board, 0, i)
put(board, 'screw', 'green', Piece.count, 0)
