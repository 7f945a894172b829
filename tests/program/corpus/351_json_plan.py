import json

plan = json.loads('[["washer", "blue", 2, 6], ["screw", "red", 2, 6]]')
for shape, color, x, y in plan:
    put(board, shape, color, x, y)
