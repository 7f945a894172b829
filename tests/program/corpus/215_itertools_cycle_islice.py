from itertools import cycle, islice

colors = cycle(['red', 'blue'])
for y, color in enumerate(islice(colors, 6)):
    put(board, 'nut', color, 3, y)
