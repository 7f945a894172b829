def spiral(n):
    x, y, dx, dy = 0, 0, 0, 1
    seen = set()
    for _ in range(n):
        yield x, y
        seen.add((x, y))
        nx, ny = x + dx, y + dy
        if not (0 <= nx < 8 and 0 <= ny < 8) or (nx, ny) in seen:
            dx, dy = dy, -dx
            nx, ny = x + dx, y + dy
        x, y = nx, ny


colors = ("red", "green", "blue", "yellow")
for i, (x, y) in enumerate(spiral(20)):
    put(board, "washer", colors[i % 4], x, y)
