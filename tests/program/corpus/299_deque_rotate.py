from collections import deque

colors = deque(['red', 'green', 'blue', 'yellow'])
for x in range(4):
    put(board, 'washer', colors[0], x, 2)
    colors.rotate(1)
