errors = []
for p in [(0, 0), (0, 0), (10, 0)]:
    try:
        put(board, "screw", "red", *p)
    except Exception as e:
        errors.append(type(e).__name__)
put(board, "washer", "blue", 5, len(errors))
