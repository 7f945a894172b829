from collections import defaultdict

stacks = defaultdict(list)
stacks[(0, 3)] += [('washer', 'red'), ('nut', 'yellow')]
stacks[(1, 3)].append(('screw', 'blue'))
for (x, y), pieces in stacks.items():
    for shape, color in pieces:
        put(board, shape, color, x, y)
