ROWS, COLS = 8, 8
BASE = 'washer'
TOP = 'screw'
COLOR = 'red'
for y in range(0, COLS, 4):
    put(board, BASE, COLOR, ROWS - 1, y)
    put(board, TOP, COLOR, ROWS - 1, y)
