items = [1, 2.0, "3", (4, 4), [5, 5]]
for y, item in enumerate(items):
    if isinstance(item, (int, float)):
        put(board, "washer", "red", int(item), y)
    elif isinstance(item, str):
        put(board, "washer", "blue", int(item), y)
    elif isinstance(item, (tuple, list)):
        put(board, "nut", "green", *item)
