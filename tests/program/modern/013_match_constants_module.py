import math

def classify(v):
    match v:
        case math.pi:
            return "red"
        case 1.0:
            return "green"
        case _:
            return "blue"

for y, v in enumerate([math.pi, 1.0, 2.5]):
    put(board, "washer", classify(v), 2, y)
