import enum


class Color(enum.Enum):
    RED = "red"
    GREEN = "green"
    BLUE = "blue"


colors = [c.value for c in Color]
names = list(Color.__members__)
for i, (name, c) in enumerate(zip(names, colors)):
    put(board, "washer", c, i, len(name))
