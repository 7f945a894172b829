from functools import lru_cache


@lru_cache(maxsize=2)
def height(x):
    return x % 3 + 1


for x in [1, 2, 1, 3, 1]:
    for _ in range(height(x)):
        pass
info = height.cache_info()
put(board, "washer", "yellow", info.hits, info.misses)
put(board, "washer", "red", info.maxsize, info.currsize)
