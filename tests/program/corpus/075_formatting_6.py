x = 2.5
put(board, 'nut', 'green', int(f'{x:.0f}'), int(format(4.2, '.0f')))
