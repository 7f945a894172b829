config = {"rows": 8, "cols": 8, "fill": "green", "extra": 1, "more": 2}
match config:
    case {"rows": r, "cols": c, **others}:
        for i, key in enumerate(sorted(others)):
            put(board, "washer", "red" if key == "fill" else "blue", r - 1 - i, c - 1)
