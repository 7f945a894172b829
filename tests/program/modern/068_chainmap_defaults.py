from collections import ChainMap

defaults = {"shape": "washer", "color": "red"}
overrides = [{"color": "blue"}, {}, {"shape": "nut", "color": "green"}]
for y, o in enumerate(overrides):
    cfg = ChainMap(o, defaults)
    put(board, cfg["shape"], cfg["color"], 2, y)
