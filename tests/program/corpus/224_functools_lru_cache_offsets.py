from functools import lru_cache

@lru_cache(maxsize=32)
def offset(i):
    return i * 2 % 8

for i in range(6):
    put(board, 'washer', 'blue', i, offset(i))
