queue = [(0, 0), (1, 2), (2, 4), (3, 6)]
while (item := queue.pop() if queue else None) is not None:
    x, y = item
    put(board, "washer", "red", x, y)
if (n := len([1, 2, 3])) > 2:
    put(board, "nut", "blue", n, n)
