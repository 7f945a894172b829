put(board, "washer", "green", 3, 6)
put(board, 'bridge-h', 'yellow', 3, 7)
