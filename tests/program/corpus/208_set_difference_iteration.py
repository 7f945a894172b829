all_colors = {'red', 'green', 'blue', 'yellow'}
used = {'red'}
for i, c in enumerate(all_colors - used):
    put(board, 'nut', c, i, 7)
