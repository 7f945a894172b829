from typing import ClassVar


class Counter:
    total: ClassVar[int] = 0
    label: str

    def __init__(self, label: str) -> None:
        self.label = label
        Counter.total += 1


cs = [Counter(c) for c in ["red", "green", "blue"]]
for c in cs:
    put(board, "washer", c.label, Counter.total, len(c.label))
