big = [0] * 1000
for i, v in enumerate(big[:3]):
    put(board, 'washer', 'red', i, v)
