colors = {i: c for i, c in enumerate(['red', 'green', 'blue'])}
for i in colors:
    put(board, 'washer', colors[i], i, 7 - i)
