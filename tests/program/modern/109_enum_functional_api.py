from enum import Enum

Color = Enum("Color", ["RED", "GREEN", "BLUE"])
for member in Color:
    put(board, "washer", member.name.lower(), member.value, member.value)
