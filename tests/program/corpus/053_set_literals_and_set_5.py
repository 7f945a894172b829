s = frozenset({5, 6})
if s.issubset({5, 6, 7}):
    for y in sorted(s):
        put(board, 'nut', 'red', 7, y)
