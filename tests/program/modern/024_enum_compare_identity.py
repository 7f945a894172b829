from enum import Enum


class Mode(Enum):
    FILL = 1
    BORDER = 2


def draw(mode):
    for x in range(8):
        for y in range(8):
            edge = x in (0, 7) or y in (0, 7)
            if mode is Mode.FILL or (mode == Mode.BORDER and edge):
                put(board, "washer", "blue", x, y)


draw(Mode.BORDER)
print(Mode.BORDER.name, Mode(1).name, Mode.FILL in Mode)
