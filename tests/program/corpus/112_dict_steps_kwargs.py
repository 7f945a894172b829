steps = [
    dict(shape='washer', color='yellow', x=1, y=6),
    dict(shape='nut', color='blue', x=1, y=6),
]
for s in steps:
    put(board, **s)
