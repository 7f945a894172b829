n = 8
mid = n // 2
put(board, 'washer', 'red', mid, mid)
put(board, 'washer', 'red', mid - 1, mid - 1)
