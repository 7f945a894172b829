sizes = {'a': 2, 'b': 3}
if all(isinstance(v, int) for v in sizes.values()):
    put(board, 'washer', 'green', max(sizes.values()), min(sizes.values()))
