from collections import namedtuple

Cell = namedtuple('Cell', 'x y')
for cell in [Cell(2, 2), Cell(x=3, y=1)]:
    put(board, 'nut', 'green', *cell)
