import random

random.seed(2024)
cells = [(x, y) for x in range(8) for y in range(8)]
random.shuffle(cells)
for x, y in cells[:6]:
    put(board, "washer", random.choice(["red", "green", "blue", "yellow"]), x, y)
