def make_placer(color):
    count = 0

    def place(x, y):
        nonlocal count
        put(board, "washer", color, x, y)
        count += 1
        return count

    return place


red = make_placer("red")
for i in range(3):
    n = red(i, 0)
put(board, "nut", "blue", n, n)
