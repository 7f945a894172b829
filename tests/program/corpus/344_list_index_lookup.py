order = ['red', 'green', 'blue', 'yellow']
for c in ['blue', 'red']:
    put(board, 'washer', c, order.index(c), 5)
