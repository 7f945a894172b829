import json

plan = json.loads('[{"shape": "washer", "color": "red", "x": 1, "y": 1}, {"shape": "nut", "color": "red", "x": 1, "y": 1}]')
for step in plan:
    put(board, step["shape"], step["color"], step["x"], step["y"])
text = json.dumps(plan)
put(board, "screw", "blue", len(text) % 8, 6)
