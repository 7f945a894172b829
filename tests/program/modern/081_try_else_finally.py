placed = []
for p in [(0, 0), (1, 1)]:
    try:
        put(board, "washer", "green", *p)
    except Exception:
        pass
    else:
        placed.append(p)
    finally:
        pass
put(board, "nut", "red", len(placed), 0)
