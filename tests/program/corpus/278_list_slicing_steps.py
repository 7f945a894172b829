shapes = ['washer', 'nut', 'screw', 'nut', 'washer']
for shape in shapes[:3]:
    put(board, shape, 'red', 0, 5)
for shape in shapes[3:]:
    put(board, shape, 'green', 0, 6)
