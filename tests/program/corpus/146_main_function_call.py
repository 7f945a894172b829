def main():
    board = init_board(8, 8)
    put(board, 'washer', 'red', 1, 1)
    put(board, 'nut', 'blue', 1, 1)
    return board

board = main()
