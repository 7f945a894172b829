def shape_for(n):
    match n:
        case int(k) if k < 0:
            return None
        case 0:
            return "washer"
        case int(k) if k % 2 == 0:
            return "nut"
        case int():
            return "screw"


for y, n in enumerate([0, 2, 3, -1, 4]):
    s = shape_for(n)
    if s is not None:
        put(board, s, "blue", 6, y)
