from enum import Enum


class Color(Enum):
    RED = "red"
    GREEN = "green"
    BLUE = "blue"
    YELLOW = "yellow"


for i, color in enumerate(Color):
    put(board, "washer", color.value, 0, i)
put(board, "nut", Color.RED.value, 0, 0)
put(board, "screw", Color["BLUE"].value, 2, len(Color))
put(board, "nut", Color("green").value, 3, 3)
