from functools import lru_cache


class Grid:
    def __init__(self, n):
        self.n = n

    @lru_cache(maxsize=128)
    def color(self, x, y):
        return "red" if (x + y) % 2 else "blue"


g = Grid(4)
for x in range(4):
    for y in range(4):
        put(board, "washer", g.color(x, y), x, y)
put(board, "nut", "green", 7, Grid.color.cache_info().hits % 8)
