import copy

draft = copy.deepcopy(board)
put(draft, 'washer', 'red', 2, 2)
put(draft, 'nut', 'blue', 2, 2)
board = draft
