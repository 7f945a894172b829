colors = ['red', 'green', 'blue', 'yellow']
for i, color in enumerate(colors):
    put(board, 'washer', color, 0, i)
