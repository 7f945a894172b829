class Vec:
    __match_args__ = ("x", "y")

    def __init__(self, x, y):
        self.x, self.y = x, y


for v in [Vec(1, 2), Vec(3, 3), Vec(0, 6)]:
    match v:
        case Vec(a, b) if a == b:
            put(board, "nut", "yellow", a, b)
        case Vec(0, b):
            put(board, "screw", "green", 0, b)
        case Vec(a, b):
            put(board, "washer", "blue", a, b)
