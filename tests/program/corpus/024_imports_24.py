import string
letters = string.ascii_uppercase[:3]
for i, ch in enumerate(letters):
    put(board, 'nut', 'green', i, ord(ch) - ord('A') + 2)
