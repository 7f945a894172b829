class Geometry:
    @staticmethod
    def line(x0, y0, x1, y1):
        n = max(abs(x1 - x0), abs(y1 - y0))
        return [(x0 + (x1 - x0) * i // n, y0 + (y1 - y0) * i // n) for i in range(n + 1)]


for x, y in Geometry.line(0, 0, 7, 3):
    put(board, "washer", "green", x, y)
