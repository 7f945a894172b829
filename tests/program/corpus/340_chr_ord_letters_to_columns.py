for letter in 'ACE':
    put(board, 'washer', 'blue', 2, ord(letter) - ord('A'))
