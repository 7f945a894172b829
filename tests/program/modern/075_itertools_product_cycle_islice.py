from itertools import cycle, islice, product

colors = cycle(["red", "blue"])
for (x, y), c in zip(product(range(0, 8, 3), repeat=2), colors):
    put(board, "washer", c, x, y)
for y, c in enumerate(islice(cycle(["green", "yellow"]), 5)):
    put(board, "nut", c, 7, y)
