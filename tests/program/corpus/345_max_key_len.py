words = ['nut', 'washer', 'screw']
put(board, max(words, key=len), 'red', 0, 0)
put(board, min(words, key=len), 'blue', 0, 0)
