class Point:
    def __init__(self, x, y):
        self.x = x
        self.y = y


def describe(p):
    match p:
        case Point(x=0, y=0):
            return "red"
        case Point(x=0, y=_):
            return "green"
        case Point(x=_, y=0):
            return "blue"
        case Point():
            return "yellow"


for p in [Point(0, 0), Point(0, 3), Point(4, 0), Point(5, 5)]:
    put(board, "washer", describe(p), p.x, p.y)
