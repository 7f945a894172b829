placed = 0


def place(shape, color, x, y):
    global placed
    put(board, shape, color, x, y)
    placed += 1


for y in range(4):
    place("washer", "green", 2, y)
place("nut", "green", 2, placed - 1)
