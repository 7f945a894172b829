todo = [('screw', 'red'), ('nut', 'blue'), ('washer', 'green')]
while todo:
    shape, color = todo.pop()
    put(board, shape, color, 1, 6)
