import math
for i in range(3):
    put(board, 'washer', 'red', int(math.sqrt(49)), i)
