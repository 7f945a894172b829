from functools import partial

place_red = partial(put, board, color='red')
place_red('washer', x=0, y=0)
place_red('nut', x=0, y=0)
