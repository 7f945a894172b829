for i in range(3):
    print(f"Placing washer {i} at ({i}, {i})")
    put(board, 'washer', 'red', i, i)
