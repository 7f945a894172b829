cells = [(0, 0), (0, 0), (1, 1)]
for x, y in cells:
    try:
        put(board, 'washer', 'red', x, y)
    except Exception as exc:
        print(f"skip ({x}, {y}): {exc}")
