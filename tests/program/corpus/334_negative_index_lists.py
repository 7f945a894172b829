cols = [0, 1, 2, 3, 4, 5, 6, 7]
put(board, 'screw', 'yellow', cols[-1], cols[-2])
put(board, 'screw', 'yellow', cols[-8], cols[-3])
