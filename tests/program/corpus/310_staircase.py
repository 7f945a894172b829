# a staircase: column y gets y + 1 pieces, washer at the bottom, a screw on the highest step
for y in range(3):
    for shape in ['washer', 'nut', 'screw'][:y + 1]:
        put(board, shape, 'blue', 7, y)
