x, y = 6, 3
print(f"{x=}, {y=}, {x + y:>4}")
put(board, 'screw', 'yellow', x, y)
