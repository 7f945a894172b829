from collections.abc import Iterable, Sequence


def flatten(items):
    for item in items:
        if isinstance(item, Iterable) and not isinstance(item, str) and not isinstance(item[0], int):
            yield from flatten(item)
        else:
            yield item


for x, y in flatten([[(0, 0), (1, 1)], [(2, 2)]]):
    put(board, "washer", "red", x, y)
