from itertools import accumulate, groupby

seq = ["red", "red", "blue", "green", "green", "green"]
for x, (color, run) in enumerate(groupby(seq)):
    for y, _ in enumerate(run):
        put(board, "washer", color, x, y)
for y, s in enumerate(accumulate([1, 2, 3])):
    put(board, "nut", "yellow", 7, s)
