color_of = {'w': 'red', 'n': 'green', 's': 'blue'}
shape_of = {'w': 'washer', 'n': 'nut', 's': 'screw'}
for letter in 'wns':
    put(board, shape_of[letter], color_of[letter], 5, 5)
