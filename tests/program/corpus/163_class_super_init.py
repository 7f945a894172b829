class Component:
    def __init__(self, shape, color):
        self.shape = shape
        self.color = color

class Bridge(Component):
    def __init__(self, color, vertical=False):
        super().__init__('bridge-v' if vertical else 'bridge-h', color)

b = Bridge('green', vertical=True)
put(board, b.shape, b.color, 2, 6)
