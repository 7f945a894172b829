class Piece:
    __slots__ = ("shape", "color", "x", "y")

    def __init__(self, shape, color, x, y):
        self.shape = shape
        self.color = color
        self.x = x
        self.y = y

    def place(self, b):
        put(b, self.shape, self.color, self.x, self.y)


pieces = [Piece("washer", "red", i, i) for i in range(4)]
for p in pieces:
    p.place(board)
try:
    pieces[0].z = 1
except AttributeError:
    put(board, "nut", "blue", 7, 0)
