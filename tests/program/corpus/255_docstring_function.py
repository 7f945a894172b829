def build_bn(board, colors, x, y):
    """Build a 'bn' object: a vertical bridge with a nut on it.

    Args:
        board: the board.
        colors: (bridge colour, nut colour).
        x, y: the top-left cell.
    """
    put(board, 'bridge-v', colors[0], x, y)
    put(board, 'nut', colors[1], x, y)

build_bn(board, ('green', 'red'), 4, 3)
