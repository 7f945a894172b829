from typing import Any, Iterable, Mapping, Sequence


def place_all(cells: Iterable[Sequence[int]], colors: Mapping[int, str], **kw: Any) -> int:
    n = 0
    for x, y in cells:
        put(board, kw.get("shape", "washer"), colors[x % 2], x, y)
        n += 1
    return n


count = place_all([(0, 1), (1, 2)], {0: "red", 1: "blue"}, shape="nut")
put(board, "screw", "green", count, count)
