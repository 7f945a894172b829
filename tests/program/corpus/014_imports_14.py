from typing import List, Tuple
def place(board, cells: List[Tuple[int, int]]) -> None:
    for x, y in cells:
        put(board, 'washer', 'red', x, y)
place(board, [(0, 0), (1, 1)])
