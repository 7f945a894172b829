def flatten(items):
    out = []
    for item in items:
        if isinstance(item, list):
            out.extend(flatten(item))
        else:
            out.append(item)
    return out

for x, y in flatten([(0, 0), [(1, 1), [(2, 2)]]]):
    put(board, 'nut', 'yellow', x, y)
