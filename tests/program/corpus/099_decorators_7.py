cells = [(x, y) for x in range(8) for y in range(8) if x == y][:3]
for x, y in cells:
    put(board, 'screw', 'green', x, y)
