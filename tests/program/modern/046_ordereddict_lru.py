from collections import OrderedDict


class Recent:
    def __init__(self, size):
        self.size = size
        self.items = OrderedDict()

    def touch(self, key):
        if key in self.items:
            self.items.move_to_end(key)
        self.items[key] = True
        if len(self.items) > self.size:
            self.items.popitem(last=False)


r = Recent(3)
for c in ["red", "blue", "red", "green", "yellow", "red"]:
    r.touch(c)
for y, c in enumerate(r.items):
    put(board, "washer", c, 4, y)
