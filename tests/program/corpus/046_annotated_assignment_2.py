colors: list[str] = ['red', 'blue']
position: tuple[int, int] = (6, 1)
for c in colors:
    put(board, 'washer' if c == 'red' else 'nut', c, *position)
