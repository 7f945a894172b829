from typing import NamedTuple

class Step(NamedTuple):
    shape: str
    color: str
    x: int
    y: int = 0

for s in [Step('washer', 'blue', 4), Step('nut', 'red', 4)]:
    put(board, *s)
