from operator import attrgetter, itemgetter


class P:
    def __init__(self, x, y, c):
        self.x, self.y, self.c = x, y, c


pts = [P(3, 1, "red"), P(1, 2, "blue"), P(2, 0, "green")]
for p in sorted(pts, key=attrgetter("x")):
    put(board, "washer", p.c, p.x, p.y)
raw = [(5, 5, "red"), (4, 6, "yellow")]
for x, y, c in sorted(raw, key=itemgetter(1)):
    put(board, "nut", c, x, y)
