import numpy as np
def place_object(board: np.ndarray, x: int, y: int) -> np.ndarray:
    put(board, 'washer', 'red', x, y)
    put(board, 'nut', 'blue', x, y)
    return board
board = place_object(board, 7, 3)
