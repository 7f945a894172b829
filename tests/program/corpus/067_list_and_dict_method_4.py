d = dict(a=1, b=2)
x = d.pop('a')
y = d.get('c', 4)
put(board, 'washer', 'yellow', x, y)
