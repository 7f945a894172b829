def place_if_free(board, x, y, used):
    if (x, y) in used:
        return False
    put(board, 'washer', 'yellow', x, y)
    used.add((x, y))
    return True

used = set()
for x, y in [(1, 1), (1, 1), (2, 3)]:
    place_if_free(board, x, y, used)
