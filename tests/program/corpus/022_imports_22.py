from collections import deque
q = deque([(0, 0), (0, 1)])
q.appendleft((5, 5))
while q:
    x, y = q.popleft()
    put(board, 'screw', 'blue', x, y)
