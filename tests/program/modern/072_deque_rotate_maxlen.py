from collections import deque

colors = deque(["red", "green", "blue", "yellow"])
for y in range(8):
    put(board, "washer", colors[0], 0, y)
    colors.rotate(-1)
recent = deque(maxlen=2)
for p in [(1, 1), (2, 2), (3, 3)]:
    recent.append(p)
for p in recent:
    put(board, "nut", "red", *p)
