def diagonal(n):
    for i in range(n):
        yield i, i

for x, y in diagonal(5):
    put(board, 'washer', 'red', x, y)
