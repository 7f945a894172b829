actions = [
    lambda b: put(b, 'washer', 'green', 3, 0),
    lambda b: put(b, 'nut', 'red', 3, 0),
    lambda b: put(b, 'screw', 'yellow', 3, 0),
]
for action in actions:
    action(board)
