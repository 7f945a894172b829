import random

random.seed(0)
for x in range(4):
    color = random.choice(['red', 'green', 'blue', 'yellow'])
    put(board, 'nut', color, x, 3)
