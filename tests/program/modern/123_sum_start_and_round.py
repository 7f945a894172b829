xs = [0.4, 1.6, 2.5]
total = sum(xs, start=1.0)
put(board, "washer", "red", round(total), int(round(2.675, 2) > 2))
put(board, "nut", "red", round(total), 1)
