names = ['Washer', ' NUT ']
put(board, names[0].lower(), 'red', 0, 0)
put(board, names[1].strip().lower(), 'blue', 0, 0)
