from collections import namedtuple

Step = namedtuple('Step', ['shape', 'color', 'x', 'y'])
steps = [Step('washer', 'red', 0, 0), Step('bridge-h', 'blue', 1, 1)]
for s in steps:
    put(board, s.shape, s.color, s.x, s.y)
