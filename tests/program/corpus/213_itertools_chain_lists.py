from itertools import chain

top = [(0, y) for y in range(3)]
bottom = [(7, y) for y in range(3)]
for x, y in chain(top, bottom):
    put(board, 'screw', 'blue', x, y)
