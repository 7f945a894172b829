count: int
count = 3
for i in range(count):
    put(board, 'nut', 'green', i, 7)
