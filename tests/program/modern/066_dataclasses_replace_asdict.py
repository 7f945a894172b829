from dataclasses import asdict, astuple, dataclass, field, replace


@dataclass
class Step:
    shape: str
    color: str
    x: int = 0
    y: int = 0
    tags: list[str] = field(default_factory=list)


base = Step("washer", "red")
steps = [replace(base, x=i, y=i) for i in range(4)]
for s in steps:
    d = asdict(s)
    put(board, d["shape"], d["color"], d["x"], d["y"])
shape, color, x, y, tags = astuple(replace(base, shape="nut", x=3, y=3))
put(board, shape, color, x, y)
