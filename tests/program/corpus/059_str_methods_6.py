line = 'red,blue,green'
for i, c in enumerate(line.split(',')):
    put(board, 'nut', c.upper().lower(), i, i + 1)
