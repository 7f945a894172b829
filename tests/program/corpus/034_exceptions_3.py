def safe_put(b, *args):
    try:
        put(b, *args)
        return True
    except Exception:
        return False
safe_put(board, 'screw', 'red', 1, 1)
safe_put(board, 'nut', 'red', 1, 1)
safe_put(board, 'nut', 'blue', 2, 2)
