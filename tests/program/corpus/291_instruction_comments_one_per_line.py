board = init_board(8, 8)
# Place a yellow bridge horizontally in the 2nd row, 2nd column.
put(board, 'bridge-h', 'yellow', 1, 1)
# Place a green bridge horizontally in the 3rd row, 3rd column.
put(board, 'bridge-h', 'green', 2, 2)
# Place a blue bridge vertically in the 2nd row, 3rd column.
put(board, 'bridge-v', 'blue', 1, 2)
# Place a red nut in the 2nd row, 3rd column.
put(board, 'nut', 'red', 1, 2)
# Place a blue screw in the 2nd row, 3rd column.
put(board, 'screw', 'blue', 1, 2)
