class Base:
    __slots__ = ["x", "y"]

    def __init__(self, x, y):
        self.x, self.y = x, y


class Colored(Base):
    __slots__ = ("color",)

    def __init__(self, x, y, color):
        super().__init__(x, y)
        self.color = color


cs = [Colored(1, 2, "green"), Colored(2, 3, "blue")]
for c in cs:
    put(board, "washer", c.color, c.x, c.y)
cs[0].x = 6
put(board, "nut", cs[0].color, cs[0].x, cs[0].y)
