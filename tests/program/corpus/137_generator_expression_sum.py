n = sum(1 for c in 'washer' if c in 'aeiou')
put(board, 'nut', 'yellow', n, n)
