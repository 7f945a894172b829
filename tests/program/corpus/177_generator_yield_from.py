def row(x):
    yield from ((x, y) for y in range(3))

def rows(xs):
    for x in xs:
        yield from row(x)

for x, y in rows([0, 2]):
    put(board, 'nut', 'yellow', x, y)
