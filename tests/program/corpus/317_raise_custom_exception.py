class PlacementError(Exception):
    pass

def place(board, x, y):
    if not (0 <= x < 8 and 0 <= y < 8):
        raise PlacementError(f"({x}, {y}) is off the board")
    put(board, 'nut', 'red', x, y)

for x, y in [(1, 1), (9, 1), (2, 2)]:
    try:
        place(board, x, y)
    except PlacementError as e:
        print(e)
