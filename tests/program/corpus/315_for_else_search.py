for y in range(8):
    if y == 4:
        put(board, 'screw', 'green', 0, y)
        break
else:
    put(board, 'screw', 'green', 7, 7)
