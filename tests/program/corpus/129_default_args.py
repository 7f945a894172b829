def place(board, x, y, shape='washer', color='red'):
    put(board, shape, color, x, y)

place(board, 0, 0)
place(board, 0, 0, 'nut')
place(board, 0, 0, color='blue', shape='screw')
