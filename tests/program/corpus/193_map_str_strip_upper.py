colors = list(map(str.strip, [' red ', 'blue\n']))
for i, c in enumerate(colors):
    put(board, 'nut', c, 7, i)
