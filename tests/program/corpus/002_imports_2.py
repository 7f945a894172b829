import math
put(board, 'nut', 'blue', math.floor(7.9), math.ceil(2.1))
