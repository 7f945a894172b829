origin = np.array([7, 7])
for d in [np.array([0, 0]), np.array([1, 1]), np.array([2, 0])]:
    x, y = origin - d
    put(board, 'screw', 'red', int(x), int(y))
