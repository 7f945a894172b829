from functools import cached_property


class Layout:
    def __init__(self, n):
        self.n = n

    @cached_property
    def cells(self):
        return [(i, (i * 3) % 8) for i in range(self.n)]


lay = Layout(5)
for x, y in lay.cells:
    put(board, "washer", "green", x, y)
put(board, "nut", "green", *lay.cells[0])
