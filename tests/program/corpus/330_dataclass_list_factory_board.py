from dataclasses import dataclass, field

@dataclass
class Layer:
    shape: str
    color: str

@dataclass
class Stack:
    x: int
    y: int
    layers: list = field(default_factory=list)

    def add(self, shape, color):
        self.layers.append(Layer(shape, color))
        return self

s = Stack(3, 6).add('washer', 'red').add('nut', 'blue').add('screw', 'yellow')
for layer in s.layers:
    put(board, layer.shape, layer.color, s.x, s.y)
