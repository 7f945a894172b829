class Vec:
    def __init__(self, x, y):
        self.x = x
        self.y = y

    def __add__(self, other):
        return Vec(self.x + other.x, self.y + other.y)

    def __mul__(self, k):
        return Vec(self.x * k, self.y * k)

    __rmul__ = __mul__


start = Vec(1, 1)
step = Vec(1, 0)
for i in range(3):
    p = start + i * step
    put(board, 'washer', 'red', p.x, p.y)
