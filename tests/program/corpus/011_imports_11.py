from functools import partial
red_washer = partial(put, board, 'washer', 'red')
red_washer(1, 1)
red_washer(2, 2)
