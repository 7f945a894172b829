def columns():
    y = 0
    while True:
        yield y
        y += 2

gen = columns()
for _ in range(4):
    put(board, 'washer', 'blue', 7, next(gen))
