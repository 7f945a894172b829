from itertools import starmap

steps = [(board, 'washer', 'blue', 1, 1), (board, 'nut', 'red', 1, 1)]
list(starmap(put, steps))
