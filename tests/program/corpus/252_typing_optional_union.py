from typing import Optional, Union

def place(board, x: int, y: Optional[int] = None, color: Union[str, None] = None) -> None:
    put(board, 'nut', color or 'yellow', x, y if y is not None else x)

place(board, 2)
place(board, 3, 5, 'red')
