from contextlib import suppress


def cells():
    yield (0, 7)
    yield (1, 7)
    return 'done'


gen = cells()
while True:
    try:
        x, y = next(gen)
    except StopIteration as stop:
        if stop.value == 'done':
            put(board, 'nut', 'blue', 7, 7)
        break
    put(board, 'washer', 'red', x, y)

colors = {'a': 'green'}
with suppress(KeyError):
    put(board, 'washer', colors['a'], 3, 3)
    put(board, 'washer', colors['b'], 4, 4)
