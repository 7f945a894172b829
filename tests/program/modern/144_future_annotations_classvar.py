from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import ClassVar


@dataclass
class Tower:
    HEIGHT: ClassVar[int] = 3
    x: int
    y: int
    _: KW_ONLY
    color: str = "red"
    parts: list[str] = field(default_factory=lambda: ["washer", "nut", "screw"])

    def build(self) -> None:
        for shape in self.parts[: Tower.HEIGHT]:
            put(board, shape, self.color, self.x, self.y)


for i, t in enumerate([Tower(1, 1), Tower(4, 6, color="blue")]):
    t.build()
