def diagonal(board, i):
    if i >= 4:
        return
    put(board, 'nut', 'blue', i, i)
    diagonal(board, i + 1)

diagonal(board, 0)
