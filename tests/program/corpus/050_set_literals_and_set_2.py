used = set()
used.add((2, 2))
used.update({(3, 3), (4, 4)})
used.discard((4, 4))
for x, y in sorted(used):
    put(board, 'nut', 'blue', x, y)
