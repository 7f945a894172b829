for i in range(8):
    if i % 2:
        continue
    if i > 5:
        break
    put(board, 'nut', 'yellow', i, 7 - i)
else:
    pass
