for i in range(3):
    msg = "step %d: washer at (%d, %d)" % (i, i, 2 * i)
    print(msg)
    put(board, 'washer', 'red', i, 2 * i)
