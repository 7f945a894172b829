import itertools

palette = itertools.cycle(['green', 'yellow', 'red'])
for x in range(5):
    put(board, 'washer', next(palette), x, 0)
