try:
    put(board, 'washer', 'red', 9, 9)
except Exception:
    put(board, 'washer', 'red', 7, 7)
