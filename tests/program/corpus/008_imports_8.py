from itertools import zip_longest
for x, y in zip_longest([1, 2, 3], [4, 5], fillvalue=0):
    put(board, 'nut', 'green', x, y)
