try:
    put(board, 'washer', 'red', 8, 0)
except Exception as e:
    print("could not place:", e)
put(board, 'washer', 'red', 7, 0)
