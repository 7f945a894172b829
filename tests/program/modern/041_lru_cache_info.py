from functools import lru_cache


@lru_cache(maxsize=None)
def fib(n):
    return n if n < 2 else fib(n - 1) + fib(n - 2)


for i in range(8):
    put(board, "washer", "blue", i, fib(i) % 8)
info = fib.cache_info()
put(board, "nut", "red", info.hits % 8, info.misses % 8)
fib.cache_clear()
put(board, "screw", "green", 7, fib.cache_info().currsize)
