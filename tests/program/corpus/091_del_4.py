def make_counter():
    n = 0
    def step():
        nonlocal n
        n += 1
        return n
    return step
next_col = make_counter()
for _ in range(3):
    put(board, 'washer', 'yellow', 3, next_col())
