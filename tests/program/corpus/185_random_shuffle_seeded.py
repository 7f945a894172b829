import random

order = [(0, 0), (1, 1), (2, 2), (3, 3)]
random.seed(7)
random.shuffle(order)
for i, (x, y) in enumerate(order):
    put(board, 'washer', ['red', 'green', 'blue', 'yellow'][i], x, y)
