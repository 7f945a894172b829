class Path:
    def __init__(self, *points):
        self.points = list(points)

    def __iter__(self):
        return iter(self.points)

    def __len__(self):
        return len(self.points)

    def __getitem__(self, i):
        return self.points[i]


p = Path((0, 0), (1, 1), (2, 2))
for x, y in p:
    put(board, "washer", "green", x, y)
put(board, "nut", "green", *p[-1])
put(board, "screw", "red", len(p), 0)
