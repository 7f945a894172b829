from functools import singledispatch


@singledispatch
def place(spec):
    raise TypeError("unknown spec")


@place.register
def _(spec: tuple):
    put(board, "washer", "red", *spec)


@place.register(str)
def _(spec):
    x, y = map(int, spec.split(","))
    put(board, "nut", "blue", x, y)


for s in [(1, 1), "2,2", (3, 3)]:
    place(s)
