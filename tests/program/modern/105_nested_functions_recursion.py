def fill(x, y, color, seen=None):
    seen = set() if seen is None else seen
    if (x, y) in seen or not (0 <= x < 4 and 0 <= y < 4):
        return seen
    seen.add((x, y))
    put(board, "washer", color, x, y)
    for dx, dy in ((1, 0), (0, 1)):
        fill(x + dx, y + dy, color, seen)
    return seen


print(len(fill(0, 0, "green")))
