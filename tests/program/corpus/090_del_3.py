count = 0
def place(x, y):
    global count
    put(board, 'washer', 'blue', x, y)
    count += 1
place(0, 1)
place(1, 0)
put(board, 'nut', 'red', count, count)
