import collections

Piece = collections.namedtuple('Piece', ['shape', 'color'])
base = Piece('washer', 'red')
top = base._replace(shape='nut')
for p in (base, top):
    put(board, p.shape, p.color, 6, 6)
