actions = [lambda i=i: put(board, 'washer', 'yellow', i, 0) for i in range(4)]
for act in actions:
    act()
