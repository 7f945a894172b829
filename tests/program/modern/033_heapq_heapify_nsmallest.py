import heapq

cells = [(5, 1), (2, 7), (0, 3), (6, 6), (1, 1)]
heapq.heapify(cells)
for x, y in heapq.nsmallest(3, cells):
    put(board, "washer", "green", x, y)
for x, y in heapq.nlargest(2, cells, key=lambda c: c[1]):
    put(board, "nut", "yellow", x, y)
