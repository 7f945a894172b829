row = 'wn' * 4
names = {'w': 'washer', 'n': 'nut'}
for y, ch in enumerate(row[:5]):
    put(board, names[ch], 'yellow', 4, y)
