class Part:
    shape = 'washer'

    def __init__(self, color):
        self.color = color

    def place(self, board, x, y):
        put(board, self.shape, self.color, x, y)

class Nut(Part):
    shape = 'nut'

class Screw(Part):
    shape = 'screw'

for part in (Part('red'), Nut('blue'), Screw('yellow')):
    part.place(board, 4, 4)
