text = 'row 7 col 3'
parts = text.partition(' col ')
put(board, 'screw', 'yellow', int(parts[0].removeprefix('row ')), int(parts[2]))
