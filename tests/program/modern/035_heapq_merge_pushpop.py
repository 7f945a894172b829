import heapq

a = [0, 2, 4]
b = [1, 3, 5]
for y, v in enumerate(heapq.merge(a, b)):
    put(board, "washer", "red", v, y)
h = [5, 7, 9]
smallest = heapq.heappushpop(h, 6)
put(board, "nut", "blue", smallest, 7)
heapq.heapreplace(h, 1)
put(board, "screw", "green", h[0], 6)
