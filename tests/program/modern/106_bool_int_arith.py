flags = [True, False, True, True]
put(board, "washer", "red", sum(flags), int(flags[1]))
put(board, "nut", "blue", flags.count(True), 7)
