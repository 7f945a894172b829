first, *middle, last = [(0, 0), (1, 1), (2, 2), (3, 3), (4, 4)]
put(board, "washer", "red", *first)
for p in middle:
    put(board, "nut", "blue", *p)
put(board, "screw", "green", *last)
head, *tail = "washer nut screw".split()
put(board, head, "yellow", 7, len(tail))
