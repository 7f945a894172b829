i = 0
while (j := i * 2) < 6:
    put(board, 'washer', 'red', i, j)
    i += 1
