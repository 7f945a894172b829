base = {'shape': 'washer', 'color': 'red'}
override = base | {'color': 'green'}
put(board, override['shape'], override['color'], 7, 3)
