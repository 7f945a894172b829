cells = [(1, 2), (3, 4)]
for i, (x, y) in enumerate(cells):
    label = f"{'washer' if i == 0 else 'nut'}"
    put(board, label, f"{'red'}", x, y)
