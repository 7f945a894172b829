import functools

washer = functools.partial(put, board, 'washer')
nut = functools.partial(put, board, 'nut')
washer('blue', 5, 5)
nut('green', 5, 5)
washer('yellow', 5, 6)
