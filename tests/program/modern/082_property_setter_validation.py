class Cursor:
    def __init__(self):
        self._x = 0

    @property
    def x(self):
        return self._x

    @x.setter
    def x(self, value):
        if not 0 <= value < 8:
            raise ValueError("x out of range")
        self._x = value


c = Cursor()
for v in [3, 9, 5]:
    try:
        c.x = v
        put(board, "washer", "blue", c.x, 1)
    except ValueError:
        put(board, "screw", "red", 7, 7)
