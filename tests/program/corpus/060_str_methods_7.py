label = 'WASHER'
put(board, label.casefold(), 'blue', 4, 0)
put(board, 'nut', 'RED'.title().lower(), 4, 0)
