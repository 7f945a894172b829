import numpy as np
from typing import List
def row(board: np.ndarray, colors: List[str], x: int) -> None:
    for y, c in enumerate(colors):
        put(board, 'washer', c, x, y)
row(board, ['red', 'blue'], 2)
