xs = [float(v) for v in ['1.0', '2.0']]
for x in xs:
    put(board, 'screw', 'blue', int(x), 5)
