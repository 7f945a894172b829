def main():
    b = init_board(8, 8)
    for y in range(4):
        put(b, 'screw', 'green', 2, y)
    return b

if __name__ == "__main__":
    board = main()
