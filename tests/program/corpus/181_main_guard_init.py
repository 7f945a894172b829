def build_object(board, x, y):
    put(board, 'bridge-h', 'yellow', x, y)

if __name__ == '__main__':
    board = init_board(8, 8)
    build_object(board, 5, 2)
    print(board)
