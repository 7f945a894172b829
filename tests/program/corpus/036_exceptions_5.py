try:
    d = {}
    d['missing']
except KeyError:
    put(board, 'washer', 'blue', 2, 3)
finally:
    put(board, 'nut', 'red', 2, 3)
