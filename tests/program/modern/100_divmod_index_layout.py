colors = ["red", "green", "blue", "yellow"]
for i in range(12):
    x, y = divmod(i, 4)
    put(board, "washer", colors[y], x, y * 2)
