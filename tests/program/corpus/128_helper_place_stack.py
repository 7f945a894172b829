def place_stack(board, x, y, pieces):
    for shape, color in pieces:
        put(board, shape, color, x, y)

place_stack(board, 2, 2, [('washer', 'red'), ('nut', 'green')])
place_stack(board, 2, 3, [('washer', 'blue'), ('nut', 'yellow')])
