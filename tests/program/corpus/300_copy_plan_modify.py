import copy

plan = [['washer', 'red', 0, 0], ['nut', 'blue', 0, 0]]
second = copy.deepcopy(plan)
for step in second:
    step[2] = 5
for step in plan + second:
    put(board, *step)
