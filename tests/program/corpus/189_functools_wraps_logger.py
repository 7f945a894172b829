from functools import wraps

def logged(func):
    @wraps(func)
    def wrapper(*args, **kwargs):
        print(f"calling {func.__name__}")
        return func(*args, **kwargs)
    return wrapper

@logged
def place(board, x, y):
    put(board, 'washer', 'green', x, y)

place(board, 3, 3)
place(board, 3, 4)
