pattern = "nws"
names = {"w": "washer", "n": "nut", "s": "screw"}
for level, ch in enumerate(pattern):
    put(board, names[ch], ["red", "green", "blue", "yellow"][level], 3, 4)
