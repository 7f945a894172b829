def check(x):
    if not 0 <= x < 8:
        raise ValueError(f'bad coordinate {x}')
    return x
try:
    check(10)
except ValueError:
    put(board, 'nut', 'green', check(4), check(5))
