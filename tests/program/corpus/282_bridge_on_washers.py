def bridge_over(board, x, y, base_color, bridge_color):
    put(board, 'washer', base_color, x, y)
    put(board, 'washer', base_color, x, y + 1)
    put(board, 'bridge-h', bridge_color, x, y)

bridge_over(board, 3, 2, 'red', 'yellow')
