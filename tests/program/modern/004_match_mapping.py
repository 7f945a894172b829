instructions = [
    {"shape": "washer", "color": "red", "pos": (2, 3)},
    {"shape": "nut", "color": "blue", "pos": (2, 3), "note": "on top"},
    {"kind": "line", "color": "green", "x": 5},
]

for ins in instructions:
    match ins:
        case {"shape": shape, "color": color, "pos": (x, y), **rest}:
            put(board, shape, color, x, y)
        case {"kind": "line", "color": color, "x": x}:
            for y in range(0, 8, 2):
                put(board, "washer", color, x, y)
