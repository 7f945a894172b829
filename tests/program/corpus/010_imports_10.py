from functools import reduce
total = reduce(lambda a, b: a + b, [1, 2, 3])
put(board, 'nut', 'yellow', total, total)
