from collections import OrderedDict

order = OrderedDict([("red", 0), ("green", 1), ("blue", 2), ("yellow", 3)])
order.move_to_end("red")
order.move_to_end("blue", last=False)
for y, (color, _) in enumerate(order.items()):
    put(board, "washer", color, 0, y)
first = order.popitem(last=False)
put(board, "nut", first[0], 0, 0)
