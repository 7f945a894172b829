for y in range(3):
    print("placing", y, sep=": ", end="\n")
    put(board, "washer", "red", 0, y)
print(*[1, 2, 3], sep=",")
