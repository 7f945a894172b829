import string

layout = """
RGB
.Y.
"""
letters = {"R": "red", "G": "green", "B": "blue", "Y": "yellow"}
for x, line in enumerate(layout.strip().splitlines()):
    for y, ch in enumerate(line):
        if ch in string.ascii_uppercase:
            put(board, "washer", letters[ch], x, y)
