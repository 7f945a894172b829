from itertools import permutations
cells = list(permutations(range(3), 2))
for x, y in cells[:4]:
    put(board, 'screw', 'red', x, y)
