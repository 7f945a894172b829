steps = [
    ('washer', 'red', 0, 0),
    ('washer', 'red', 0, 1),
    ('bridge-h', 'blue', 0, 0),
    ('nut', 'yellow', 0, 0),
]
board = init_board(8, 8)
for step in steps:
    put(board, *step)
