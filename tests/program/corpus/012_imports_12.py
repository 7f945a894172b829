from functools import lru_cache
@lru_cache(maxsize=None)
def col(i):
    return (i * 3) % 8
for i in range(4):
    put(board, 'nut', 'blue', i, col(i))
