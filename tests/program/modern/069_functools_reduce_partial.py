from functools import partial, reduce
import operator

place_red = partial(put, board, "washer", "red")
for y in range(3):
    place_red(0, y)
total = reduce(operator.add, [1, 2, 3], 0)
put(board, "nut", "blue", total, 0)
product = reduce(lambda a, b: a * b, range(1, 4))
put(board, "screw", "green", product, 7)
