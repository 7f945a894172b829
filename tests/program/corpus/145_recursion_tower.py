def tower(board, x, y, pieces):
    if not pieces:
        return board
    shape, color = pieces[0]
    put(board, shape, color, x, y)
    return tower(board, x, y, pieces[1:])

board = tower(board, 4, 1, [('washer', 'red'), ('nut', 'blue'), ('screw', 'green')])
