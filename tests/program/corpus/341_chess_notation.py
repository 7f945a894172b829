def cell(square):
    col = 'abcdefgh'.index(square[0])
    row = 8 - int(square[1])
    return row, col

for sq in ['a1', 'h8', 'd4']:
    put(board, 'nut', 'green', *cell(sq))
