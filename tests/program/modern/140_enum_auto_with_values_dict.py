from enum import Enum, auto


class Piece(Enum):
    WASHER = auto()
    NUT = auto()

    @property
    def label(self):
        return self.name.lower()


stacks = {Piece.WASHER: [(0, 0), (1, 0)], Piece.NUT: [(0, 0)]}
for piece in Piece:
    for x, y in stacks[piece]:
        put(board, piece.label, "red", x, y)
print(Piece.WASHER.value, Piece.NUT < Piece.WASHER if False else True)
