class ObjectSpec:
    def __init__(self, name, shapes, colors):
        self.name = name
        self.shapes = shapes
        self.colors = colors

    def build(self, board, x, y):
        for shape, color in zip(self.shapes, self.colors):
            put(board, shape, color, x, y)

spec = ObjectSpec('wns', ['washer', 'nut', 'screw'], ['red', 'green', 'blue'])
spec.build(board, 6, 1)
