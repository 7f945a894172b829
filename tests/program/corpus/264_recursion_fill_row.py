def fill(board, x, y, end):
    if y > end:
        return
    put(board, 'washer', 'blue', x, y)
    fill(board, x, y + 1, end)

fill(board, 6, 2, 5)
