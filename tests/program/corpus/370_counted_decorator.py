def counted(func):
    def wrapper(*args, **kwargs):
        wrapper.calls += 1
        return func(*args, **kwargs)
    wrapper.calls = 0
    return wrapper


@counted
def place(shape, color, x, y):
    put(board, shape, color, x, y)


for y in range(3):
    place('washer', 'blue', 4, y)
place('nut', 'red', place.calls, 6)
