from itertools import count

for y, shape in zip(count(2), ['washer', 'nut', 'screw']):
    put(board, shape, 'green', 0, y)
