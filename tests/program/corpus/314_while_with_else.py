y = 0
while y < 3:
    put(board, 'washer', 'red', 5, y)
    y += 1
else:
    put(board, 'nut', 'blue', 5, y)
