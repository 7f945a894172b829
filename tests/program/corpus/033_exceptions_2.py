try:
    put(board, 'washer', 'purple', 0, 0)
except Exception as e:
    msg = str(e)
    put(board, 'washer', 'red', 0, 0)
