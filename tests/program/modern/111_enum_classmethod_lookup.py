from enum import Enum


class Color(Enum):
    RED = "r"
    GREEN = "g"
    BLUE = "b"

    @classmethod
    def from_letter(cls, letter):
        for c in cls:
            if c.value == letter:
                return c
        raise ValueError(letter)


for y, letter in enumerate("rgbbg"):
    put(board, "washer", Color.from_letter(letter).name.lower(), 3, y)
