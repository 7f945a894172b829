specs = ["shape:washer@red", "shape:nut@blue", "shape:screw@green"]
for y, spec in enumerate(specs):
    shape, color = spec.removeprefix("shape:").split("@")
    put(board, shape, color.removesuffix("!"), 0, y)
