tmp = 5
del tmp
put(board, 'nut', 'green', 5, 5)
