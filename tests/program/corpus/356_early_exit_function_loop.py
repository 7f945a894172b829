def place_until(board, limit):
    for y in range(8):
        if y == limit:
            return y
        put(board, 'washer', 'blue', 3, y)
    return 8

last = place_until(board, 5)
put(board, 'screw', 'red', 4, last)
