from dataclasses import dataclass

@dataclass(order=True)
class Spot:
    x: int
    y: int

spots = sorted([Spot(3, 3), Spot(1, 5), Spot(1, 2)])
for s in spots:
    put(board, 'washer', 'green', s.x, s.y)
