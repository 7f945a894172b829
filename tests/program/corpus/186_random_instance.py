from random import Random

rng = Random(123)
for y in rng.sample(range(8), 3):
    put(board, 'screw', 'yellow', 6, y)
