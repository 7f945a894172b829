place = lambda x, y: put(board, 'washer', 'yellow', x, y)
for i in range(3):
    place(i, 0)
