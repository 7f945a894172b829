import typing
def f(x: typing.Any) -> typing.Union[int, None]:
    return x
put(board, 'screw', 'yellow', f(3), f(4))
