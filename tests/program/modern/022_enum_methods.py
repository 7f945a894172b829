from enum import Enum


class Direction(Enum):
    NORTH = (-1, 0)
    SOUTH = (1, 0)
    EAST = (0, 1)
    WEST = (0, -1)

    def move(self, x, y):
        dx, dy = self.value
        return x + dx, y + dy

    @property
    def opposite(self):
        return {Direction.NORTH: Direction.SOUTH, Direction.SOUTH: Direction.NORTH,
                Direction.EAST: Direction.WEST, Direction.WEST: Direction.EAST}[self]


x, y = 4, 4
for d in [Direction.NORTH, Direction.EAST, Direction.EAST, Direction.SOUTH.opposite]:
    x, y = d.move(x, y)
    put(board, "washer", "green", x, y)
