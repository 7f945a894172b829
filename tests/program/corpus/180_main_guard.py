def build(board):
    put(board, 'washer', 'red', 0, 0)
    put(board, 'nut', 'blue', 0, 0)

if __name__ == "__main__":
    build(board)
