class PlacementError(Exception):
    def __init__(self, x, y, reason):
        super().__init__(f"cannot place at ({x}, {y}): {reason}")
        self.x, self.y = x, y


def safe_place(x, y):
    try:
        if not (0 <= x < 8 and 0 <= y < 8):
            raise ValueError("off board")
        put(board, "washer", "red", x, y)
    except ValueError as exc:
        raise PlacementError(x, y, str(exc)) from exc


for x, y in [(1, 1), (9, 9), (2, 2)]:
    try:
        safe_place(x, y)
    except PlacementError as e:
        put(board, "nut", "blue", 0, len(str(e)) % 8)
