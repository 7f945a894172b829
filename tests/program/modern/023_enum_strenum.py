from enum import StrEnum


class Color(StrEnum):
    RED = "red"
    BLUE = "blue"


for y, c in enumerate(Color):
    put(board, "washer", str(c), 1, y)
put(board, "nut", Color.BLUE.value, 1, 1)
print(f"done with {Color.RED}")
