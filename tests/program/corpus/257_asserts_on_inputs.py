def place(board, shape, color, x, y):
    assert shape in ('washer', 'nut', 'screw', 'bridge-h', 'bridge-v'), shape
    assert color in ('red', 'green', 'blue', 'yellow'), color
    assert 0 <= x < 8 and 0 <= y < 8
    put(board, shape, color, x, y)

place(board, 'washer', 'green', 2, 2)
place(board, 'screw', 'red', 2, 2)
