grid = [
    ["red", "blue", "green"],
    ["yellow", "red", "blue"],
]
for y, column in enumerate(zip(*grid)):
    for x, color in enumerate(column):
        put(board, "washer", color, x, y)
