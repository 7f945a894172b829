word = 'washer'
put(board, word, 'yellow', word.count('a') + word.index('h'), len(word))
