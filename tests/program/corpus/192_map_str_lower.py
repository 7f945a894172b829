names = ['WASHER', 'Nut', 'SCREW']
for shape in map(str.lower, names):
    put(board, shape, 'green', 4, 4)
