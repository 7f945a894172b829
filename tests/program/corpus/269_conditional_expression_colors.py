for y in range(6):
    color = 'red' if y % 2 == 0 else 'blue'
    put(board, 'washer', color, 4, y)
