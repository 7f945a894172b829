moves = ["up", "down", "left", "right", "stay"]
x, y = 4, 4
for move in moves:
    match move:
        case "up" | "north" as d:
            x -= 1
        case "down" | "south":
            x += 1
        case ("left" | "right") as d:
            y += -1 if d == "left" else 1
        case other:
            pass
    put(board, "washer", "green", x, y) if (x, y) != (4, 4) else None
put(board, "nut", "red", x, y)
