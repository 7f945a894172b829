todo = [(0, 0), (0, 1), (0, 2)]
todo.remove((0, 1))
first = todo.copy()
todo.clear()
for x, y in first:
    put(board, 'nut', 'blue', x, y)
