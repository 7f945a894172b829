values = [3, 8, 1, 9, 5]
picked = [y for v in values if (y := v - 1) < 8]
for i, y in enumerate(picked):
    put(board, "washer", "green", i, y)
