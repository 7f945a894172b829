class Piece:
    def __init__(self, shape, color, x, y):
        self.shape, self.color, self.x, self.y = shape, color, x, y

    @classmethod
    def from_string(cls, text):
        shape, color, x, y = text.split()
        return cls(shape, color, int(x), int(y))

    def __str__(self):
        return f"{self.color} {self.shape} at ({self.x}, {self.y})"


for line in ["washer red 0 0", "nut red 0 0", "washer blue 4 4"]:
    p = Piece.from_string(line)
    put(board, p.shape, p.color, p.x, p.y)
    print(str(p))
