from enum import Enum


class Shape(str, Enum):
    WASHER = "washer"
    NUT = "nut"

    def __str__(self):
        return self.value


for y, s in enumerate(Shape):
    put(board, str(s), "red", 6, y)
print(Shape.NUT == "nut")
