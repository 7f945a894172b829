pairs = {frozenset({"red", "blue"}): (1, 1), frozenset({"green"}): (2, 2)}
for key, (x, y) in pairs.items():
    for color in sorted(key):
        put(board, "washer", color, x, y + len(key) - 1)
