id = 2
input = 'red'
put(board, 'screw', input, id, id)
