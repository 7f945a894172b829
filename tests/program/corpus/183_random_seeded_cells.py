import random

random.seed(42)
cells = set()
while len(cells) < 5:
    cells.add((random.randint(0, 7), random.randint(0, 7)))
for x, y in sorted(cells):
    put(board, 'washer', 'blue', x, y)
