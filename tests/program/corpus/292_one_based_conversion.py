def to_cell(row, col):
    return row - 1, col - 1

put(board, 'washer', 'green', *to_cell(8, 4))
put(board, 'nut', 'red', *to_cell(8, 4))
put(board, 'screw', 'blue', *to_cell(1, 1))
