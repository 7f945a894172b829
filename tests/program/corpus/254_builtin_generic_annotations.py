def build(board, plan: list[tuple[str, str]], x: int, y: int) -> dict[str, int]:
    for shape, color in plan:
        put(board, shape, color, x, y)
    return {'placed': len(plan)}

info = build(board, [('washer', 'green'), ('nut', 'blue')], 1, 5)
