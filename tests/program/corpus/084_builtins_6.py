cells = [(i, chr(ord('a') + i)) for i in range(3)]
for i, ch in cells:
    put(board, 'washer', 'red', i, ord(ch) - 97 + 4)
