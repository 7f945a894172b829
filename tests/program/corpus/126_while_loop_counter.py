i = 0
while i < 5:
    put(board, 'washer', 'green', i, 0)
    i += 1
