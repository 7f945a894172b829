x: int = 2
y: int = 5
put(board, 'washer', 'red', x, y)
