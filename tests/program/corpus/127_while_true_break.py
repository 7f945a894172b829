x = 7
while True:
    put(board, 'nut', 'yellow', x, 7 - x)
    x -= 1
    if x < 4:
        break
