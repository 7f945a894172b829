from typing import Generic, Iterable, Iterator, TypeVar

T = TypeVar("T")


class Queue(Generic[T]):
    def __init__(self) -> None:
        self.items: list[T] = []

    def push(self, item: T) -> None:
        self.items.append(item)

    def __iter__(self) -> Iterator[T]:
        return iter(self.items)


q: Queue[tuple[int, int]] = Queue()
for p in [(0, 1), (1, 2), (2, 3)]:
    q.push(p)
for x, y in q:
    put(board, "nut", "red", x, y)
