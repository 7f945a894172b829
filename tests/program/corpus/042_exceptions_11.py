def place(b, x, y):
    assert isinstance(x, int) and isinstance(y, int)
    put(b, 'washer', 'blue', x, y)
place(board, 1, 6)
