sum = 0
for v in [1, 2]:
    sum += v
max = 5
put(board, 'washer', 'blue', sum, max)
