from typing import Callable

def apply(f: Callable[[int, int], None], cells):
    for x, y in cells:
        f(x, y)

apply(lambda x, y: put(board, 'screw', 'blue', x, y), [(6, 6), (6, 7)])
