def parse(lines):
    for line in lines:
        shape, color, x, y = line.split()
        yield shape, color, int(x), int(y)

def only_valid(steps):
    for s in steps:
        if 0 <= s[2] < 8 and 0 <= s[3] < 8:
            yield s

for step in only_valid(parse(['washer red 1 1', 'nut blue 9 9', 'nut blue 1 1'])):
    put(board, *step)
