commands = [("place", "washer", "red", 0, 0), ("place", "nut", "blue", 0, 0), ("skip",), ("row", 3, "green")]

for cmd in commands:
    match cmd:
        case ("place", shape, color, x, y):
            put(board, shape, color, x, y)
        case ("row", x, color):
            for y in range(8):
                put(board, "washer", color, x, y)
        case ("skip",):
            pass
        case _:
            raise ValueError(f"unknown command {cmd}")
