moves = ["a1", "b2", "c3", "h8"]
for m in moves:
    y = ord(m[0]) - ord("a")
    x = 8 - int(m[1])
    put(board, "washer", "yellow", x, y)
print(chr(ord("a") + 2))
