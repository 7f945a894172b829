from collections import Counter
c = Counter(['red', 'red', 'blue'])
for i, (color, n) in enumerate(c.most_common()):
    put(board, 'washer', color, i, n)
