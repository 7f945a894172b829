class Grid:
    @staticmethod
    def cells(n):
        return [(i, n - 1 - i) for i in range(n)]

for x, y in Grid.cells(4):
    put(board, 'washer', 'blue', x, y)
