class Cobot:
    """Keeps track of what it placed."""

    def __init__(self, board):
        self.board = board
        self.log = []

    def put(self, shape, color, x, y):
        put(self.board, shape, color, x, y)
        self.log.append((shape, color, x, y))

robot = Cobot(board)
robot.put('washer', 'green', 0, 7)
robot.put('nut', 'red', 0, 7)
put(board, 'washer', 'blue', len(robot.log), 7)
