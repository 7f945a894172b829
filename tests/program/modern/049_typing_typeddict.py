from typing import TypedDict


class Step(TypedDict):
    shape: str
    color: str
    x: int
    y: int


steps: list[Step] = [
    {"shape": "washer", "color": "blue", "x": 0, "y": 0},
    Step(shape="nut", color="blue", x=0, y=0),
]
for s in steps:
    put(board, s["shape"], s["color"], s["x"], s["y"])
