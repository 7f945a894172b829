from collections import Counter

wanted = ["red", "blue", "red", "green", "red", "blue"]
counts = Counter(wanted)
for y, (color, n) in enumerate(counts.most_common()):
    for x in range(n):
        put(board, "washer", color, x, y)
print(counts.total())
