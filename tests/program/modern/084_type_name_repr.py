class Block:
    def __init__(self, x, y):
        self.x, self.y = x, y

    def __repr__(self):
        return f"{type(self).__name__}({self.x}, {self.y})"


blocks = [Block(1, 2), Block(3, 4)]
for b in blocks:
    put(board, "washer", "red", b.x, b.y)
put(board, "nut", "blue", len(repr(blocks[0])) % 8, 0)
