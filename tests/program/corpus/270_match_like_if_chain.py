def shape_for(code):
    if code == 'W':
        return 'washer'
    elif code == 'N':
        return 'nut'
    elif code == 'S':
        return 'screw'
    return 'bridge-h'

for y, code in enumerate('WNS'):
    put(board, shape_for(code), 'green', 5, y)
