x = y = 0
count = 0
while count < 8:
    put(board, "washer", "red", x, y)
    x, y = (x + 1) % 8, (y + 3) % 8
    count += 1
else:
    put(board, "nut", "red", 0, 0)
