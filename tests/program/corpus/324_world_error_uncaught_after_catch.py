try:
    put(board, 'washer', 'red', 0, 8)
except Exception:
    pass
put(board, 'washer', 'red', 0, 7)
put(board, 'washer', 'green', 0, 7)
