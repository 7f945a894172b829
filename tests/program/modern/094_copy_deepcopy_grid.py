import copy

template = [["washer", "red"], ["nut", "blue"]]
layers = [copy.deepcopy(template) for _ in range(2)]
layers[1][0][1] = "green"
for x, layer in enumerate(layers):
    for shape, color in layer:
        put(board, shape, color, x, 0)
