import functools
import operator

x = functools.reduce(operator.add, [1, 2, 3])
put(board, 'nut', 'yellow', x, x)
