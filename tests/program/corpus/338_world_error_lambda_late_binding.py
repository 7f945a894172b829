actions = [lambda: put(board, 'washer', 'red', 0, i) for i in range(3)]
for act in actions:
    act()
