from typing import List, Tuple, Dict

Cell = Tuple[int, int]

def cells_of(rows: int, col: int) -> List[Cell]:
    return [(r, col) for r in range(rows)]

colors: Dict[int, str] = {0: 'red', 1: 'green', 2: 'blue'}
for x, y in cells_of(3, 5):
    put(board, 'washer', colors[x], x, y)
