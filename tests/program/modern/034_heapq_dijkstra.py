from heapq import heappop, heappush

walls = {(1, 1), (1, 2), (1, 3), (3, 4), (4, 4)}
start, goal = (0, 0), (5, 5)
dist = {start: 0}
prev = {}
queue = [(0, start)]
while queue:
    d, cur = heappop(queue)
    if cur == goal:
        break
    if d > dist[cur]:
        continue
    x, y = cur
    for nxt in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
        if 0 <= nxt[0] < 8 and 0 <= nxt[1] < 8 and nxt not in walls:
            if d + 1 < dist.get(nxt, 99):
                dist[nxt] = d + 1
                prev[nxt] = cur
                heappush(queue, (d + 1, nxt))
node = goal
while node != start:
    put(board, "washer", "blue", *node)
    node = prev[node]
put(board, "washer", "red", *start)
