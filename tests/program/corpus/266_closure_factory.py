def make_placer(shape, color):
    def placer(x, y):
        put(board, shape, color, x, y)
    return placer

red_washer = make_placer('washer', 'red')
blue_nut = make_placer('nut', 'blue')
red_washer(0, 4)
blue_nut(0, 4)
