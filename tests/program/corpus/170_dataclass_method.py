from dataclasses import dataclass
from typing import List, Tuple

@dataclass
class Assembly:
    name: str
    parts: List[Tuple[str, str]]

    def build(self, board, x: int, y: int) -> None:
        for shape, color in self.parts:
            put(board, shape, color, x, y)

Assembly('wn', [('washer', 'blue'), ('nut', 'yellow')]).build(board, 7, 7)
