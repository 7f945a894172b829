import statistics

xs = [1, 3, 5, 7]
mid = int(statistics.mean(xs))
med = int(statistics.median([2, 6, 4]))
put(board, "washer", "red", mid, med)
