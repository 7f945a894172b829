from typing import Callable

Placer = Callable[[int, int], None]


def washer(x: int, y: int) -> None:
    put(board, "washer", "green", x, y)


def repeat(f: Placer, n: int) -> None:
    for i in range(n):
        f(i, 7 - i)


repeat(washer, 8)
