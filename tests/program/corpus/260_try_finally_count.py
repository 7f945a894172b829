placed = 0
try:
    for y in range(3):
        put(board, 'nut', 'blue', 5, y)
        placed += 1
finally:
    print(placed)
put(board, 'screw', 'yellow', 6, placed)
