class Row:
    def __init__(self, x, n):
        self.x = x
        self.n = n

    def __iter__(self):
        return iter([(self.x, y) for y in range(self.n)])

    def __len__(self):
        return self.n

row = Row(3, 5)
for x, y in row:
    put(board, 'nut', 'blue', x, y)
put(board, 'screw', 'red', len(row), 0)
