class Cell:
    def __init__(self, x, y):
        self.x, self.y = x, y

    def __eq__(self, other):
        return isinstance(other, Cell) and (self.x, self.y) == (other.x, other.y)

    def __hash__(self):
        return hash((self.x, self.y))


cells = {Cell(1, 1), Cell(1, 1), Cell(2, 3)}
for c in sorted(cells, key=lambda c: (c.x, c.y)):
    put(board, "washer", "yellow", c.x, c.y)
