from itertools import repeat

for color, y in zip(repeat('yellow'), range(4)):
    put(board, 'washer', color, 2, y)
