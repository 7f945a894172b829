import functools
@functools.cache
def fib(n):
    return n if n < 2 else fib(n - 1) + fib(n - 2)
put(board, 'washer', 'red', fib(5), fib(4))
