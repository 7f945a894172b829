instruction = "Place a red washer in the 2nd row, 3rd column"
words = instruction.replace(',', '').split()
color, shape = words[2], words[3]
row = int(words[6][0]) - 1
col = int(words[8][0]) - 1
put(board, shape, color, row, col)
