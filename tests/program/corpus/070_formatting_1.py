label = '{}-{}'.format('washer', 'red')
shape, color = label.split('-')
put(board, shape, color, 0, 7)
