def place(x, y):
    assert 0 <= x < 8, "x out of range"
    assert 0 <= y < 8
    put(board, "washer", "red", x, y)


for i in range(3):
    place(i, 7 - i)
