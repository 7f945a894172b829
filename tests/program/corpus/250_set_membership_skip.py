occupied = set()
for x, y in [(3, 3), (3, 3), (4, 4)]:
    if (x, y) in occupied:
        continue
    put(board, 'washer', 'red', x, y)
    occupied.add((x, y))
