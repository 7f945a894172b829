def split(board, lo, hi):
    if lo > hi:
        return
    mid = (lo + hi) // 2
    put(board, 'nut', 'red', 3, mid)
    split(board, lo, mid - 1)
    split(board, mid + 1, hi)

split(board, 0, 6)
