put(board, 'bridge-h', 'yellow', 3, 7)
