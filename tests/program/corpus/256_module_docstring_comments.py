"""Build the object from the instructions."""
# Start with an empty 8x8 board.
board = init_board(8, 8)

# Bottom: a blue washer in the 8th row, 1st column.
put(board, 'washer', 'blue', 7, 0)  # (x=7, y=0)
# Then a yellow nut on top of it.
put(board, 'nut', 'yellow', 7, 0)
