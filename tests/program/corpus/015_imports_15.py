from typing import Dict, Optional
def build(board, colors: Dict[str, str], row: Optional[int] = None):
    r = 7 if row is None else row
    put(board, 'washer', colors['base'], r, 0)
    put(board, 'nut', colors['top'], r, 0)
    return board
board = build(board, {'base': 'red', 'top': 'blue'})
