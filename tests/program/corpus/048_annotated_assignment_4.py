def make(board: 'Board', shape: str = 'washer') -> 'Board':
    put(board, shape, 'red', 0, 5)
    return board
board = make(board)
