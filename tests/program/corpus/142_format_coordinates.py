label = "{},{}".format(6, 1)
x, y = map(int, label.split(","))
put(board, 'screw', 'blue', x, y)
