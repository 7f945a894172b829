def place_all(items):
    match items:
        case []:
            return
        case [first, *rest]:
            x, y = first
            put(board, "screw", "yellow", x, y)
            place_all(rest)

place_all([(1, 1), (2, 2), (3, 3), (4, 4)])
