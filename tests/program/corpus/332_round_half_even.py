put(board, 'washer', 'red', round(2.5), round(3.5))
put(board, 'nut', 'blue', round(0.5), round(1.5))
