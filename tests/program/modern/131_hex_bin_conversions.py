mask = 0b1011
for y in range(4):
    if mask >> y & 1:
        put(board, "washer", "blue", 1, y)
put(board, "nut", "red", int("7", 16), len(bin(5)) - 2)
put(board, "screw", "green", int(hex(3), 16), 6)
