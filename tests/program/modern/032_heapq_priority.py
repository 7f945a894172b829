import heapq

tasks = []
heapq.heappush(tasks, (3, "screw", "red", 2, 2))
heapq.heappush(tasks, (1, "washer", "red", 2, 2))
heapq.heappush(tasks, (2, "nut", "blue", 2, 2))
while tasks:
    _, shape, color, x, y = heapq.heappop(tasks)
    put(board, shape, color, x, y)
