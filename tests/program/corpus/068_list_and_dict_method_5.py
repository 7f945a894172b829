stack = []
stack.append(('washer', 'red'))
stack.insert(0, ('nut', 'blue'))
for shape, color in reversed(stack):
    put(board, shape, color, 6, 6)
