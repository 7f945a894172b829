def color_for(code):
    match code:
        case 0:
            return "red"
        case 1:
            return "green"
        case 2 | 3:
            return "blue"
        case _:
            return "yellow"

for i in range(5):
    put(board, "washer", color_for(i), i, 0)
