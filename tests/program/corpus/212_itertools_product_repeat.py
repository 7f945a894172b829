import itertools

for dx, dy in itertools.product([0, 1], repeat=2):
    put(board, 'nut', 'green', 6 + dx, 6 + dy)
