center = (3, 3)
for d in range(-2, 3):
    put(board, 'nut', 'red', center[0] + d, center[1])
    if d:
        put(board, 'nut', 'red', center[0], center[1] + d)
